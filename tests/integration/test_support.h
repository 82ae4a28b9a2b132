// Shared helpers of the integration and service tests: clouds to upload, files to
// read, temporary directories.
#pragma once

#include <cstdint>
#include <string>

#include "relmap/v1/relevance_service.pb.h"

namespace relmap::testing {

// A synthetic tabletop (perception/synthetic_tabletop.h) in the packed layout of
// the API; `seed` draws its depth noise and table texture, so that two seeds give
// two different clouds of the same scene.
v1::Cloud PackedTabletop(std::uint32_t width = 320, std::uint32_t height = 240,
                         std::uint32_t seed = 1);

// The whole of the file at `path`; fails the current test and returns "" when it
// cannot be read.
std::string ReadFile(const std::string& path);

// A new, empty directory under ::testing::TempDir(), named after the current test
// and the process, removed with everything in it when the object goes.
class TemporaryDirectory {
 public:
  TemporaryDirectory();
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace relmap::testing
