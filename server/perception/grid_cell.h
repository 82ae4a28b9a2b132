// The key of the cubic grid cell a point falls in, for the grids anchored at the origin
// (pre-voxelisation, the thinning of raw points for FPFH).
#pragma once

#include <cmath>
#include <cstdint>

namespace relmap::perception {

// Cell (floor(x / size), floor(y / size), floor(z / size)) packed in 21 bits per axis.
// Coordinates are bounded (DecodeLimits::max_abs_coordinate), so 21 bits hold any cell
// index down to 0.1 mm cells; `inverse_size` is 1 / size.
inline std::uint64_t GridCellKey(float x, float y, float z, float inverse_size) {
  const auto cell = [inverse_size](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * inverse_size)) +
                                      (1 << 20)) &
           0x1fffff;
  };
  return cell(x) | (cell(y) << 21) | (cell(z) << 42);
}

}  // namespace relmap::perception
