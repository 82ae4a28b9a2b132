// One pass over the points: per supervoxel, points and points on moveable bodies.
#include "ground_truth.h"

#include <string>

namespace relmap::sim {

StatusOr<std::vector<bool>> SupervoxelGroundTruth(
    const CameraFrame& frame, const v1::ComputeMapsResponse& maps,
    const std::function<bool(std::int32_t body_id)>& is_moveable) {
  const auto& labels = maps.point_labels();
  if (static_cast<std::size_t>(labels.size()) != frame.points.size()) {
    return InvalidArgumentError("the server labelled " + std::to_string(labels.size()) +
                                " points, the frame has " + std::to_string(frame.points.size()) +
                                " (were the point labels omitted?)");
  }
  if (frame.body_ids.size() != frame.points.size()) {
    return InvalidArgumentError("the frame has " + std::to_string(frame.body_ids.size()) +
                                " body ids for " + std::to_string(frame.points.size()) + " points");
  }
  // Supervoxel ids are small (0, 1, ... per frame): index them through a vector.
  std::vector<int> index_of_id;
  for (int i = 0; i < maps.supervoxels_size(); ++i) {
    const std::uint32_t id = maps.supervoxels(i).id();
    if (id >= index_of_id.size()) index_of_id.resize(id + 1, -1);
    index_of_id[id] = i;
  }
  std::vector<std::size_t> points(static_cast<std::size_t>(maps.supervoxels_size()), 0);
  std::vector<std::size_t> on_moveable(points.size(), 0);
  for (std::size_t p = 0; p < frame.points.size(); ++p) {
    const std::int32_t label = labels[static_cast<int>(p)];
    if (label < 0) continue;
    const auto id = static_cast<std::size_t>(label);
    if (id >= index_of_id.size() || index_of_id[id] < 0) {
      return InvalidArgumentError("point " + std::to_string(p) + " has supervoxel " +
                                  std::to_string(label) + ", which the maps do not list");
    }
    const auto i = static_cast<std::size_t>(index_of_id[id]);
    ++points[i];
    const std::int32_t body = frame.body_ids[p];
    if (body != kNoBody && is_moveable(body)) ++on_moveable[i];
  }
  std::vector<bool> object(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    object[i] = points[i] > 0 && static_cast<double>(on_moveable[i]) >=
                                     kObjectFraction * static_cast<double>(points[i]);
  }
  return object;
}

}  // namespace relmap::sim
