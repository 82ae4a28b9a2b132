// The packed binary layout of the API: 16 bytes per point (see decode.h; not in docs/method.md).
#include <cstring>
#include <string>
#include <vector>

#include "perception/decode.h"

namespace relmap::perception {

StatusOr<Cloud> DecodePacked(std::string_view bytes, std::uint32_t width, std::uint32_t height,
                             const DecodeLimits& limits) {
  const StatusOr<std::uint64_t> count = DeclaredPoints(width, height, limits);
  if (!count.ok()) return count.status();
  const std::uint64_t expected = *count * kPackedPointBytes;  // count <= max_points
  if (bytes.size() != expected) {
    return InvalidArgumentError(
        "packed cloud: " + std::to_string(width) + "x" + std::to_string(height) + " points need " +
        std::to_string(expected) + " bytes (16 per point), got " + std::to_string(bytes.size()));
  }
  // x86-64 and ARM64 are little endian, like the layout: plain copies suffice.
  std::vector<CloudPoint> points(static_cast<std::size_t>(*count));
  const char* p = bytes.data();
  for (CloudPoint& point : points) {
    std::memcpy(&point.x, p, 4);
    std::memcpy(&point.y, p + 4, 4);
    std::memcpy(&point.z, p + 8, 4);
    point.r = static_cast<std::uint8_t>(p[12]);
    point.g = static_cast<std::uint8_t>(p[13]);
    point.b = static_cast<std::uint8_t>(p[14]);
    point.a = static_cast<std::uint8_t>(p[15]);
    p += kPackedPointBytes;
  }
  return MakeCloud(width, height, std::move(points), limits);
}

}  // namespace relmap::perception
