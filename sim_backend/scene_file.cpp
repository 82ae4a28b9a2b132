// Finding, reading and parsing scene files.
#include "scene_file.h"

#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene_validation.h"

namespace relmap::sim {
namespace fs = std::filesystem;

std::string ScenesDirectory() {
  if (const char* dir = std::getenv("RELMAP_SIM_SCENES_DIR"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  return RELMAP_SIM_SCENES_DIR;
}

std::vector<std::string> ShippedSceneFiles() {
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(ScenesDirectory(), error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

StatusOr<std::string> FindSceneFile(const std::string& name_or_path) {
  std::error_code error;
  if (fs::is_regular_file(name_or_path, error)) return name_or_path;
  const fs::path shipped = fs::path(ScenesDirectory()) / (name_or_path + ".json");
  if (name_or_path.find('/') == std::string::npos && fs::is_regular_file(shipped, error)) {
    return shipped.string();
  }
  std::string names;
  for (const std::string& file : ShippedSceneFiles()) {
    names += (names.empty() ? "" : ", ") + fs::path(file).stem().string();
  }
  return NotFoundError("scene '" + name_or_path + "' not found: no such file, and no " +
                       shipped.string() + " (shipped scenes: " + names + ")");
}

StatusOr<Scene> ParseScene(std::string_view json, const std::string& file_label) {
  Scene scene;
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = false;
  const auto parsed = google::protobuf::util::JsonStringToMessage(
      google::protobuf::StringPiece(json.data(), json.size()), &scene, options);
  if (!parsed.ok()) {
    return InvalidArgumentError(file_label + ": not a valid scene file (JSON of " +
                                "scene_schema.proto's Scene): " + std::string(parsed.message()));
  }
  if (Status valid = ValidateScene(scene, file_label); !valid.ok()) return valid;
  return scene;
}

StatusOr<SceneFile> ReadSceneFile(const std::string& name_or_path) {
  StatusOr<std::string> path = FindSceneFile(name_or_path);
  if (!path.ok()) return path.status();
  std::ifstream in(*path, std::ios::binary);
  if (!in) return NotFoundError("cannot open scene file " + *path);
  std::ostringstream text;
  text << in.rdbuf();
  StatusOr<Scene> scene = ParseScene(text.str(), fs::path(*path).filename().string());
  if (!scene.ok()) return scene.status();
  return SceneFile{*path, std::move(scene).value()};
}

}  // namespace relmap::sim
