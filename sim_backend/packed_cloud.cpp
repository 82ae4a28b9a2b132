// Byte layout written explicitly (not by memcpy of a struct) so that padding and the
// host's byte order cannot leak into the wire format.
#include "packed_cloud.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace relmap::sim {
namespace {

void PutFloat(float value, char* out) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  for (int byte = 0; byte < 4; ++byte) out[byte] = static_cast<char>((bits >> (8 * byte)) & 0xff);
}

}  // namespace

v1::Cloud PackCloud(const CameraFrame& frame) {
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  std::string bytes(frame.points.size() * kPackedPointBytes, '\0');
  char* out = bytes.data();
  for (const CameraPoint& p : frame.points) {
    // A hole is a hole in all three coordinates, whatever the camera left in the others.
    const bool hole = !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    PutFloat(hole ? kNan : p.x, out);
    PutFloat(hole ? kNan : p.y, out + 4);
    PutFloat(hole ? kNan : p.z, out + 8);
    out[12] = static_cast<char>(p.r);
    out[13] = static_cast<char>(p.g);
    out[14] = static_cast<char>(p.b);
    out[15] = static_cast<char>(0xff);
    out += kPackedPointBytes;
  }
  v1::Cloud cloud;
  v1::PackedCloud* packed = cloud.mutable_packed();
  packed->set_width(frame.width);
  packed->set_height(frame.height);
  packed->set_points(std::move(bytes));
  return cloud;
}

}  // namespace relmap::sim
