// Reading PCD files (ascii, binary, binary_compressed) into plain points, without PCL:
// the server's decoder builds its clouds from these, and the CLI renders maps over the
// same points, so both read a file exactly alike.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/pcd/point.h"
#include "common/status.h"

namespace relmap::pcd {

struct ReadLimits {
  std::uint64_t max_points = 1280ULL * 960ULL;
  std::uint64_t max_bytes = 256ULL << 20;
};

// width x height points, row-major; holes as the file has them (NaN).
struct Points {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<Point> points;
};

// A PCD file with fields x y z (float32 or float64) and rgb or rgba (4 bytes); other
// fields are skipped. INVALID_ARGUMENT naming the header line, size or value that is
// wrong; RESOURCE_EXHAUSTED beyond `limits`.
StatusOr<Points> ReadPcd(std::string_view bytes, const ReadLimits& limits = {});

// The bytes of a file of at most `max_bytes`: NOT_FOUND when it cannot be opened.
StatusOr<std::string> ReadFileBytes(const std::string& path, std::uint64_t max_bytes);

}  // namespace relmap::pcd
