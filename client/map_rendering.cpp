// Colours per supervoxel, then per point through the server's point labels.
#include "map_rendering.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <unordered_map>

#include "perception/pcd_encoder.h"

namespace relmap::client {
namespace {

constexpr image::Rgb kTargetOutline = {0, 255, 0};
constexpr image::Rgb kHole = {255, 255, 255};

std::uint8_t Channel(double unit) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(unit, 0.0, 1.0)));
}

// Outside every supervoxel: the point's own brightness squeezed into [80, 176], a grey
// that neither ramp produces, so the scene stays readable around the maps.
image::Rgb Unlabelled(const perception::CloudPoint& p) {
  const double brightness = (0.299 * p.r + 0.587 * p.g + 0.114 * p.b) / 255.0;
  const auto grey = static_cast<std::uint8_t>(80 + std::lround(96.0 * brightness));
  return {grey, grey, grey};
}

// Whether point `i` of the target lies on its border: a 4-neighbour of another label
// or off the picture. Unorganized clouds have no neighbours: all their points are border.
bool OnTargetBorder(const perception::Cloud& cloud,
                    const google::protobuf::RepeatedField<std::int32_t>& labels, std::size_t i) {
  if (!cloud.organized()) return true;
  const std::size_t width = cloud.width(), x = i % width, y = i / width;
  const std::int32_t label = labels[static_cast<int>(i)];
  const auto differs = [&](std::size_t j) { return labels[static_cast<int>(j)] != label; };
  return x == 0 || y == 0 || x + 1 == width || y + 1 == cloud.height() || differs(i - 1) ||
         differs(i + 1) || differs(i - width) || differs(i + width);
}

}  // namespace

image::Rgb RelevanceColour(double relevance) {
  const std::uint8_t level = Channel(relevance);
  return {level, level, 0};
}

image::Rgb ChoiceColour(double choice, double max_choice) {
  const double t = max_choice > 0 ? choice / max_choice : 0.0;
  return {Channel(t), 0, Channel(1.0 - t)};
}

StatusOr<std::vector<image::ColouredPoint>> ColourPoints(const perception::Cloud& cloud,
                                                         const v1::ComputeMapsResponse& maps,
                                                         MapKind kind) {
  const auto& labels = maps.point_labels();
  if (static_cast<std::size_t>(labels.size()) != cloud.size()) {
    return InvalidArgumentError("the server labelled " + std::to_string(labels.size()) +
                                " points, the cloud has " + std::to_string(cloud.size()) +
                                ": not the cloud of this frame");
  }
  double max_choice = 0;
  for (const v1::Supervoxel& s : maps.supervoxels()) max_choice = std::max(max_choice, s.choice());
  std::unordered_map<std::int32_t, image::Rgb> colour_of;
  for (const v1::Supervoxel& s : maps.supervoxels()) {
    colour_of[static_cast<std::int32_t>(s.id())] = kind == MapKind::kRelevance
                                                       ? RelevanceColour(s.relevance())
                                                       : ChoiceColour(s.choice(), max_choice);
  }
  const std::int32_t target =
      maps.has_target_supervoxel_id() ? static_cast<std::int32_t>(maps.target_supervoxel_id()) : -1;
  std::vector<image::ColouredPoint> points(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const perception::CloudPoint p = cloud.point(i);
    const std::int32_t label = labels[static_cast<int>(i)];
    image::Rgb colour = kHole;
    if (label >= 0) {
      const auto it = colour_of.find(label);
      if (it == colour_of.end()) {
        return InvalidArgumentError("point " + std::to_string(i) + " has supervoxel " +
                                    std::to_string(label) + ", which the maps do not list");
      }
      colour = label == target && OnTargetBorder(cloud, labels, i) ? kTargetOutline : it->second;
    } else if (std::isfinite(p.x)) {
      colour = Unlabelled(p);
    }
    points[i] = {p.x, p.y, p.z, colour};
  }
  return points;
}

Status WriteMapPng(const perception::Cloud& cloud, const v1::ComputeMapsResponse& maps,
                   MapKind kind, const std::string& path) {
  StatusOr<std::vector<image::ColouredPoint>> points = ColourPoints(cloud, maps, kind);
  if (!points.ok()) return points.status();
  return image::WritePng(image::RasterisePoints(*points, cloud.width(), cloud.height(), kHole),
                         path);
}

Status WriteRelevancePcd(const perception::Cloud& cloud, const v1::ComputeMapsResponse& maps,
                         const std::string& path) {
  StatusOr<std::vector<image::ColouredPoint>> coloured =
      ColourPoints(cloud, maps, MapKind::kRelevance);
  if (!coloured.ok()) return coloured.status();
  std::vector<perception::CloudPoint> points(coloured->size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const image::ColouredPoint& p = (*coloured)[i];
    points[i] = {p.x, p.y, p.z, p.colour[0], p.colour[1], p.colour[2], 255};
  }
  std::ofstream out(path, std::ios::binary);
  const std::string pcd = perception::EncodePcd(cloud.width(), cloud.height(), points);
  if (!out.write(pcd.data(), static_cast<std::streamsize>(pcd.size()))) {
    return InternalError("cannot write " + path);
  }
  return OkStatus();
}

}  // namespace relmap::client
