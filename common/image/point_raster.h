// Points of a cloud as a picture: organized clouds pixel for pixel, unorganized ones as a
// top-down (x–z) projection. Shared by the segmentation and the map renderings.
#pragma once

#include <cstdint>
#include <vector>

#include "common/image/image.h"

namespace relmap::image {

// A point in the camera frame and the colour to draw it in; NaN x marks a hole.
struct ColouredPoint {
  float x = 0, y = 0, z = 0;
  Rgb colour{};
};

// `points` row-major, `width` × `height` of them. Organized (height > 1): one pixel per
// point, holes in `background`. Unorganized: x to the right and depth upwards, 800 px
// across the larger of the two extents, later points drawn over earlier ones.
Image RasterisePoints(const std::vector<ColouredPoint>& points, std::uint32_t width,
                      std::uint32_t height, Rgb background);

}  // namespace relmap::image
