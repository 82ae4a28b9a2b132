// Renders the segmentation with relmap's image library (one PNG writer for the project).
#include "segmentation_png.h"

#include <cstdint>
#include <vector>

#include "common/image/point_raster.h"

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
  std::vector<image::ColouredPoint> points(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    points[i] = {p.x, p.y, p.z, LabelColour(labels[i])};
  }
  return image::WritePng(image::RasterisePoints(points, cloud.width(), cloud.height(), {0, 0, 0}),
                         path);
}

}  // namespace relmap::perception
