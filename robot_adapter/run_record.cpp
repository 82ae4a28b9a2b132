// Writing and reading the run directory.
#include "run_record.h"

#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace relmap::robot {
namespace fs = std::filesystem;
namespace {

StatusOr<std::string> ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFoundError("cannot read " + path);
  return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

std::string IterationDirectory(const std::string& run_dir, int iteration) {
  char name[16];
  std::snprintf(name, sizeof name, "%06d", iteration);
  return (fs::path(run_dir) / name).string();
}

std::vector<int> RecordedIterations(const std::string& run_dir) {
  std::vector<int> iterations;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(run_dir, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || name.size() != 6 ||
        !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      continue;
    }
    iterations.push_back(std::stoi(name));
  }
  std::sort(iterations.begin(), iterations.end());
  return iterations;
}

Status WriteFile(const std::string& path, const std::string& bytes) {
  std::error_code error;
  fs::create_directories(fs::path(path).parent_path(), error);
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) return InternalError("cannot write " + partial);
  }
  fs::rename(partial, path, error);
  if (error) return InternalError("cannot rename " + partial + ": " + error.message());
  return OkStatus();
}

Status WriteJson(const std::string& path, const google::protobuf::Message& message) {
  std::string json;
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.always_print_primitive_fields = true;
  options.preserve_proto_field_names = true;
  const auto printed = google::protobuf::util::MessageToJsonString(message, &json, options);
  if (!printed.ok()) return InternalError(path + ": " + std::string(printed.message()));
  return WriteFile(path, json);
}

Status ReadJson(const std::string& path, google::protobuf::Message* message) {
  StatusOr<std::string> json = ReadBytes(path);
  if (!json.ok()) return json.status();
  const auto parsed = google::protobuf::util::JsonStringToMessage(*json, message);
  if (!parsed.ok()) return InvalidArgumentError(path + ": " + std::string(parsed.message()));
  return OkStatus();
}

Status WriteCloud(const std::string& directory, const std::string& stem, const v1::Cloud& cloud) {
  if (cloud.has_pcd()) return WriteFile(directory + "/" + stem + ".pcd", cloud.pcd());
  return WriteFile(directory + "/" + stem + ".cloud", cloud.SerializeAsString());
}

StatusOr<v1::Cloud> ReadCloud(const std::string& directory, const std::string& stem) {
  v1::Cloud cloud;
  if (StatusOr<std::string> pcd = ReadBytes(directory + "/" + stem + ".pcd"); pcd.ok()) {
    cloud.set_pcd(std::move(pcd).value());
    return cloud;
  }
  StatusOr<std::string> packed = ReadBytes(directory + "/" + stem + ".cloud");
  if (!packed.ok())
    return NotFoundError("no " + stem + ".pcd or " + stem + ".cloud in " + directory);
  if (!cloud.ParseFromString(*packed)) {
    return InvalidArgumentError(directory + "/" + stem + ".cloud is not a serialised v1.Cloud");
  }
  return cloud;
}

}  // namespace relmap::robot
