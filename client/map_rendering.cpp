// Colours per supervoxel, then per point through the server's point labels.
#include "map_rendering.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace relmap::client {
namespace {

constexpr image::Rgb kTargetOutline = {0, 255, 0};
constexpr image::Rgb kHole = {255, 255, 255};

std::uint8_t Channel(double unit) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(unit, 0.0, 1.0)));
}

// Outside every supervoxel: the point's own brightness squeezed into [80, 176], a grey
// that neither ramp produces, so the scene stays readable around the maps.
image::Rgb Unlabelled(const image::Rgb& own) {
  const double brightness = (0.299 * own[0] + 0.587 * own[1] + 0.114 * own[2]) / 255.0;
  const auto grey = static_cast<std::uint8_t>(80 + std::lround(96.0 * brightness));
  return {grey, grey, grey};
}

// Whether point `i` of the target lies on its border: a 4-neighbour of another label
// or off the picture. Unorganized clouds have no neighbours: all their points are border.
bool OnTargetBorder(std::uint32_t width, std::uint32_t height,
                    const google::protobuf::RepeatedField<std::int32_t>& labels, std::size_t i) {
  if (height <= 1) return true;
  const std::size_t x = i % width, y = i / width;
  const std::int32_t label = labels[static_cast<int>(i)];
  const auto differs = [&](std::size_t j) { return labels[static_cast<int>(j)] != label; };
  return x == 0 || y == 0 || x + 1 == width || y + 1 == height || differs(i - 1) ||
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

StatusOr<std::vector<image::ColouredPoint>> ColourPoints(
    std::uint32_t width, std::uint32_t height, const std::vector<image::ColouredPoint>& points,
    const v1::ComputeMapsResponse& maps, MapKind kind) {
  if (points.size() != static_cast<std::size_t>(width) * height) {
    return InvalidArgumentError(std::to_string(points.size()) + " points do not make a " +
                                std::to_string(width) + "x" + std::to_string(height) + " cloud");
  }
  const auto& labels = maps.point_labels();
  if (static_cast<std::size_t>(labels.size()) != points.size()) {
    return InvalidArgumentError("the server labelled " + std::to_string(labels.size()) +
                                " points, the cloud has " + std::to_string(points.size()) +
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
  std::vector<image::ColouredPoint> coloured(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const image::ColouredPoint& p = points[i];
    const std::int32_t label = labels[static_cast<int>(i)];
    image::Rgb colour = kHole;
    if (label >= 0) {
      const auto it = colour_of.find(label);
      if (it == colour_of.end()) {
        return InvalidArgumentError("point " + std::to_string(i) + " has supervoxel " +
                                    std::to_string(label) + ", which the maps do not list");
      }
      colour =
          label == target && OnTargetBorder(width, height, labels, i) ? kTargetOutline : it->second;
    } else if (std::isfinite(p.x)) {
      colour = Unlabelled(p.colour);
    }
    coloured[i] = {p.x, p.y, p.z, colour};
  }
  return coloured;
}

Status WriteMapPng(std::uint32_t width, std::uint32_t height,
                   const std::vector<image::ColouredPoint>& points,
                   const v1::ComputeMapsResponse& maps, MapKind kind, const std::string& path) {
  StatusOr<std::vector<image::ColouredPoint>> coloured =
      ColourPoints(width, height, points, maps, kind);
  if (!coloured.ok()) return coloured.status();
  return image::WritePng(image::RasterisePoints(*coloured, width, height, kHole), path);
}

}  // namespace relmap::client
