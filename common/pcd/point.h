// One point of an RGB-D cloud as plain data, the unit of every PCD read and written.
#pragma once

#include <cmath>
#include <cstdint>

namespace relmap::pcd {

// A hole of a depth camera has NaN x, y, z.
struct Point {
  float x = 0, y = 0, z = 0;
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

// Whether the point has a position: not a hole, and no coordinate a decoder let through
// as NaN or infinite.
inline bool HasPosition(const Point& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace relmap::pcd
