// Writing clouds as PCD files, the format PCL's tools and viewers read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/pcd/point.h"

namespace relmap::pcd {

// A binary PCD v0.7 file with fields x y z rgb, as PCL writes a PointXYZRGB cloud
// (rgb is the float whose bits are 0x00RRGGBB). `points` row-major, `width` ×
// `height` of them; holes stay NaN. ReadPcd reads it back exactly.
std::string EncodePcd(std::uint32_t width, std::uint32_t height, const std::vector<Point>& points);

}  // namespace relmap::pcd
