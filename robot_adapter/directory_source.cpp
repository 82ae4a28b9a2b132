// PCD files of a directory, in name order.
#include "directory_source.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "relevance_client.h"

namespace relmap::robot {
namespace fs = std::filesystem;

DirectorySource::DirectorySource(std::string directory, Options options,
                                 const std::atomic<bool>* stop)
    : directory_(std::move(directory)), options_(options), stop_(stop) {}

StatusOr<std::string> DirectorySource::FirstUnread() const {
  std::error_code error;
  if (!fs::is_directory(directory_, error)) {
    return NotFoundError("cloud directory " + directory_ + " does not exist");
  }
  std::string first;
  for (const auto& entry : fs::directory_iterator(directory_, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || entry.path().extension() != ".pcd") continue;
    if (read_.count(name) == 0 && (first.empty() || name < first)) first = name;
  }
  return first;
}

StatusOr<std::optional<SourceFrame>> DirectorySource::Next() {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    StatusOr<std::string> name = FirstUnread();
    if (!name.ok()) return name.status();
    if (!name->empty()) {
      const std::string path = (fs::path(directory_) / *name).string();
      std::ifstream in(path, std::ios::binary);
      if (!in) return NotFoundError("cannot open " + path);
      std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      read_.insert(*name);
      SourceFrame frame;
      frame.cloud = client::PcdCloud(std::move(bytes));
      return std::optional<SourceFrame>(std::move(frame));
    }
    const bool timed_out = options_.wait_timeout.count() > 0 &&
                           std::chrono::steady_clock::now() - start >= options_.wait_timeout;
    if (!options_.wait_for_files || timed_out || (stop_ != nullptr && stop_->load())) {
      return std::optional<SourceFrame>();
    }
    std::this_thread::sleep_for(options_.poll);
  }
}

}  // namespace relmap::robot
