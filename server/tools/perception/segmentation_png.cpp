// Renders the segmentation with relmap's image library (one PNG writer for the project).
#include "segmentation_png.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "image/image.h"

namespace relmap::perception {
namespace {

image::Rgb LabelColour(std::int32_t label) {
  if (label < 0) return {0, 0, 0};
  std::uint32_t h = static_cast<std::uint32_t>(label) * 2654435761u;  // Knuth's hash
  h ^= h >> 15;
  return {static_cast<std::uint8_t>(64 + (h & 0xbf)),
          static_cast<std::uint8_t>(64 + ((h >> 8) & 0xbf)),
          static_cast<std::uint8_t>(64 + ((h >> 16) & 0xbf))};
}

}  // namespace

Status WriteSegmentationPng(const Frame& frame, const std::string& path) {
  const Cloud& cloud = frame.cloud;
  const std::vector<std::int32_t>& labels = frame.segmentation.point_labels;
  if (cloud.organized()) {
    const auto width = static_cast<int>(cloud.width());
    image::Image picture(width, static_cast<int>(cloud.height()), {0, 0, 0});
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      picture.Set(static_cast<int>(i % cloud.width()), static_cast<int>(i / cloud.width()),
                  LabelColour(labels[i]));
    }
    return image::WritePng(picture, path);
  }
  // Top-down: x to the right, z (depth) upwards in the image, 800 px across the x-z extent.
  float min_x = INFINITY, max_x = -INFINITY, min_z = INFINITY, max_z = -INFINITY;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    if (!std::isfinite(p.x)) continue;
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_z = std::min(min_z, p.z), max_z = std::max(max_z, p.z);
  }
  const float extent = std::max({max_x - min_x, max_z - min_z, 1e-3f});
  const int size = 800;
  const float scale = static_cast<float>(size - 1) / extent;
  image::Image picture(size, size, {0, 0, 0});
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    if (!std::isfinite(p.x)) continue;
    const auto x = static_cast<int>((p.x - min_x) * scale);
    const auto y = size - 1 - static_cast<int>((p.z - min_z) * scale);
    picture.Set(x, y, LabelColour(labels[i]));
  }
  return image::WritePng(picture, path);
}

}  // namespace relmap::perception
