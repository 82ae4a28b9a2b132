// One pass over the points: per supervoxel, points and points on moveable bodies; or,
// for one supervoxel, points and points a push displaced.
#include "ground_truth.h"

#include <string>

namespace relmap::sim {
namespace {

// The frame and the maps label the same points, one body id each.
Status CheckLabelsMatch(const CameraFrame& frame, const v1::ComputeMapsResponse& maps) {
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
  return OkStatus();
}

// Per point of the frame, the index in maps.supervoxels() of its supervoxel, or -1 for
// a point the server left out.
StatusOr<std::vector<int>> PointSupervoxels(const CameraFrame& frame,
                                            const v1::ComputeMapsResponse& maps) {
  if (Status status = CheckLabelsMatch(frame, maps); !status.ok()) return status;
  const auto& labels = maps.point_labels();
  // Supervoxel ids are small (0, 1, ... per frame): index them through a vector.
  std::vector<int> index_of_id;
  for (int i = 0; i < maps.supervoxels_size(); ++i) {
    const std::uint32_t id = maps.supervoxels(i).id();
    if (id >= index_of_id.size()) index_of_id.resize(id + 1, -1);
    index_of_id[id] = i;
  }
  std::vector<int> index(frame.points.size(), -1);
  for (std::size_t p = 0; p < frame.points.size(); ++p) {
    const std::int32_t label = labels[static_cast<int>(p)];
    if (label < 0) continue;
    const auto id = static_cast<std::size_t>(label);
    if (id >= index_of_id.size() || index_of_id[id] < 0) {
      return InvalidArgumentError("point " + std::to_string(p) + " has supervoxel " +
                                  std::to_string(label) + ", which the maps do not list");
    }
    index[p] = index_of_id[id];
  }
  return index;
}

}  // namespace

StatusOr<std::vector<bool>> SupervoxelGroundTruth(
    const CameraFrame& frame, const v1::ComputeMapsResponse& maps,
    const std::function<bool(std::int32_t body_id)>& is_moveable) {
  auto index = PointSupervoxels(frame, maps);
  if (!index.ok()) return index.status();
  std::vector<std::size_t> points(static_cast<std::size_t>(maps.supervoxels_size()), 0);
  std::vector<std::size_t> on_moveable(points.size(), 0);
  for (std::size_t p = 0; p < frame.points.size(); ++p) {
    const int i = (*index)[p];
    if (i < 0) continue;
    ++points[static_cast<std::size_t>(i)];
    const std::int32_t body = frame.body_ids[p];
    if (body != kNoBody && is_moveable(body)) ++on_moveable[static_cast<std::size_t>(i)];
  }
  std::vector<bool> object(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    object[i] = points[i] > 0 && static_cast<double>(on_moveable[i]) >=
                                     kObjectFraction * static_cast<double>(points[i]);
  }
  return object;
}

StatusOr<std::vector<std::int32_t>> SupervoxelBodies(const CameraFrame& frame,
                                                     const v1::ComputeMapsResponse& maps) {
  auto index = PointSupervoxels(frame, maps);
  if (!index.ok()) return index.status();
  // Boyer–Moore majority vote per supervoxel, then a count to confirm it.
  const auto n = static_cast<std::size_t>(maps.supervoxels_size());
  std::vector<std::int32_t> candidate(n, kNoBody);
  std::vector<std::size_t> votes(n, 0), points(n, 0), on_candidate(n, 0);
  for (std::size_t p = 0; p < frame.points.size(); ++p) {
    if ((*index)[p] < 0) continue;
    const auto i = static_cast<std::size_t>((*index)[p]);
    ++points[i];
    if (votes[i] == 0) candidate[i] = frame.body_ids[p];
    if (candidate[i] == frame.body_ids[p]) {
      ++votes[i];
    } else {
      --votes[i];
    }
  }
  for (std::size_t p = 0; p < frame.points.size(); ++p) {
    if ((*index)[p] < 0) continue;
    const auto i = static_cast<std::size_t>((*index)[p]);
    on_candidate[i] += candidate[i] == frame.body_ids[p] ? 1 : 0;
  }
  std::vector<std::int32_t> bodies(n, kNoBody);
  for (std::size_t i = 0; i < n; ++i) {
    if (points[i] > 0 &&
        static_cast<double>(on_candidate[i]) >= kObjectFraction * static_cast<double>(points[i])) {
      bodies[i] = candidate[i];
    }
  }
  return bodies;
}

StatusOr<SupervoxelDisplacement> DisplacementOf(const CameraFrame& frame,
                                                const v1::ComputeMapsResponse& maps,
                                                std::uint32_t supervoxel_id,
                                                const PushReport& push) {
  if (Status status = CheckLabelsMatch(frame, maps); !status.ok()) return status;
  const auto& labels = maps.point_labels();
  const auto threshold = static_cast<float>(push.motion_threshold);
  SupervoxelDisplacement displacement;
  for (std::size_t p = 0; p < frame.points.size(); ++p) {
    if (labels[static_cast<int>(p)] != static_cast<std::int64_t>(supervoxel_id)) continue;
    ++displacement.points;
    const std::int32_t body = frame.body_ids[p];
    if (body == kNoBody) continue;
    if (static_cast<std::size_t>(body) >= push.body_motions.size()) {
      return InvalidArgumentError("point " + std::to_string(p) + " hit body " +
                                  std::to_string(body) + ", of which the push says nothing");
    }
    const CameraPoint& c = frame.points[p];
    const Eigen::Vector3f point(c.x, c.y, c.z);
    if ((push.body_motions[static_cast<std::size_t>(body)] * point - point).norm() > threshold) {
      ++displacement.displaced;
    }
  }
  return displacement;
}

}  // namespace relmap::sim
