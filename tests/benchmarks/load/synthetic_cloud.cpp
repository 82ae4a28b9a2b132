// Packs the synthetic tabletop's points into PackedCloud's 16-byte records.
#include "synthetic_cloud.h"

#include <bit>
#include <cstddef>
#include <string>

#include "common/synthetic_tabletop.h"

namespace relmap::load {
namespace {

using pcd::Point;

// pcd::Point is already the packed record (x y z as float32, then r g b a) on a
// little-endian machine, so the points are copied as one block.
static_assert(std::endian::native == std::endian::little);
static_assert(sizeof(Point) == 16 && offsetof(Point, y) == 4 && offsetof(Point, z) == 8 &&
              offsetof(Point, r) == 12 && offsetof(Point, g) == 13 && offsetof(Point, b) == 14 &&
              offsetof(Point, a) == 15);

}  // namespace

LoadCloud MakeSyntheticCloud(std::uint32_t width, std::uint32_t height) {
  synthetic::TabletopOptions options;
  options.width = width;
  options.height = height;
  synthetic::Tabletop scene = synthetic::MakeTabletop(options);
  const std::vector<Point>& points = scene.points;

  LoadCloud cloud;
  v1::PackedCloud* packed = cloud.cloud.mutable_packed();
  packed->set_width(width);
  packed->set_height(height);
  packed->set_points(
      std::string(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(Point)));
  cloud.description = "synthetic " + std::to_string(width) + "x" + std::to_string(height);
  cloud.object_of_point = std::move(scene.object_of_point);
  return cloud;
}

}  // namespace relmap::load
