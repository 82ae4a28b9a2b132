// The points of a PCD file as coloured points, handed to map_rendering.cpp.
#include "map_rendering_pcd.h"

#include <fstream>

#include "common/pcd/pcd_encoder.h"

namespace relmap::client {
namespace {

// The points of `cloud` in their own colours.
std::vector<image::ColouredPoint> OwnColours(const pcd::Points& cloud) {
  std::vector<image::ColouredPoint> points(cloud.points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const pcd::Point& p = cloud.points[i];
    points[i] = {p.x, p.y, p.z, {p.r, p.g, p.b}};
  }
  return points;
}

}  // namespace

StatusOr<std::vector<image::ColouredPoint>> ColourPoints(const pcd::Points& cloud,
                                                         const v1::ComputeMapsResponse& maps,
                                                         MapKind kind) {
  return ColourPoints(cloud.width, cloud.height, OwnColours(cloud), maps, kind);
}

Status WriteMapPng(const pcd::Points& cloud, const v1::ComputeMapsResponse& maps, MapKind kind,
                   const std::string& path) {
  return WriteMapPng(cloud.width, cloud.height, OwnColours(cloud), maps, kind, path);
}

Status WriteRelevancePcd(const pcd::Points& cloud, const v1::ComputeMapsResponse& maps,
                         const std::string& path) {
  StatusOr<std::vector<image::ColouredPoint>> coloured =
      ColourPoints(cloud, maps, MapKind::kRelevance);
  if (!coloured.ok()) return coloured.status();
  std::vector<pcd::Point> points(coloured->size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const image::ColouredPoint& p = (*coloured)[i];
    points[i] = {p.x, p.y, p.z, p.colour[0], p.colour[1], p.colour[2], 255};
  }
  std::ofstream out(path, std::ios::binary);
  const std::string pcd = pcd::EncodePcd(cloud.width, cloud.height, points);
  if (!out.write(pcd.data(), static_cast<std::streamsize>(pcd.size()))) {
    return InternalError("cannot write " + path);
  }
  return OkStatus();
}

}  // namespace relmap::client
