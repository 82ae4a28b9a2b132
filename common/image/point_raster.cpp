// Pixel-for-pixel copy or orthographic projection, nothing more.
#include "common/image/point_raster.h"

#include <algorithm>
#include <cmath>

namespace relmap::image {

Image RasterisePoints(const std::vector<ColouredPoint>& points, std::uint32_t width,
                      std::uint32_t height, Rgb background) {
  if (height > 1) {
    Image picture(static_cast<int>(width), static_cast<int>(height), background);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!std::isfinite(points[i].x)) continue;
      picture.Set(static_cast<int>(i % width), static_cast<int>(i / width), points[i].colour);
    }
    return picture;
  }
  float min_x = INFINITY, max_x = -INFINITY, min_z = INFINITY, max_z = -INFINITY;
  for (const ColouredPoint& p : points) {
    if (!std::isfinite(p.x)) continue;
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_z = std::min(min_z, p.z), max_z = std::max(max_z, p.z);
  }
  const float extent = std::max({max_x - min_x, max_z - min_z, 1e-3f});
  const int size = 800;
  const float scale = static_cast<float>(size - 1) / extent;
  Image picture(size, size, background);
  for (const ColouredPoint& p : points) {
    if (!std::isfinite(p.x)) continue;
    picture.Set(static_cast<int>((p.x - min_x) * scale),
                size - 1 - static_cast<int>((p.z - min_z) * scale), p.colour);
  }
  return picture;
}

}  // namespace relmap::image
