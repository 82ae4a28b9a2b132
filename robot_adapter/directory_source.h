// A cloud source over a directory of PCD files (a camera that drops one file per
// frame, or a recorded sequence): the files in name order, each once; optionally
// waiting for new ones. A writer should write elsewhere and rename into the
// directory, so that no file is read half-written.
#pragma once

#include <atomic>
#include <chrono>
#include <set>
#include <string>

#include "cloud_source.h"

namespace relmap::robot {

class DirectorySource final : public CloudSource {
 public:
  struct Options {
    bool wait_for_files = false;
    std::chrono::milliseconds poll{500};
    // 0: wait until `stop` (if any) says so.
    std::chrono::milliseconds wait_timeout{0};
  };
  // `stop`, when not null, ends a wait (Next() then answers nullopt).
  DirectorySource(std::string directory, Options options, const std::atomic<bool>* stop = nullptr);

  // The first *.pcd file (by name) not read yet. NOT_FOUND when the directory does not
  // exist; nullopt when none is left (after waiting, if asked to).
  StatusOr<std::optional<SourceFrame>> Next() override;

 private:
  // The name of the first unread PCD file, or empty.
  StatusOr<std::string> FirstUnread() const;

  std::string directory_;
  Options options_;
  const std::atomic<bool>* stop_;
  std::set<std::string> read_;
};

}  // namespace relmap::robot
