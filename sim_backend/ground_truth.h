// Ground truth of a relevance map (docs/method.md §6): a supervoxel is part of a moveable
// object when at least half of its points hit a moveable body. Ground truth of a push:
// the pushed supervoxel moved when at least half of its points were displaced by more
// than the scene's motion threshold. The points of a
// supervoxel come from the server's point labels (ComputeMapsResponse.point_labels),
// their bodies from the simulator (CameraFrame.body_ids).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"
#include "simulated_scene.h"

namespace relmap::sim {

// The object fraction at and above which a supervoxel counts as moveable.
inline constexpr double kObjectFraction = 0.5;

// Per supervoxel of `maps`, in the order of maps.supervoxels(): true for an object
// (δ = 0), false for background (δ = 1). A supervoxel without points is background.
// INVALID_ARGUMENT when the maps do not label exactly the frame's points, the frame
// has not one body id per point, or a point names a supervoxel the maps do not list.
StatusOr<std::vector<bool>> SupervoxelGroundTruth(
    const CameraFrame& frame, const v1::ComputeMapsResponse& maps,
    const std::function<bool(std::int32_t body_id)>& is_moveable);

// Per supervoxel of `maps`, in the order of maps.supervoxels(): the body that at least
// kObjectFraction of its points hit, or kNoBody (no such body, or no points). Which
// supervoxels show the same object: those a push of one of them moves with it.
// INVALID_ARGUMENT as SupervoxelGroundTruth.
StatusOr<std::vector<std::int32_t>> SupervoxelBodies(const CameraFrame& frame,
                                                     const v1::ComputeMapsResponse& maps);

// What a push did to the points of one supervoxel: each point moved with the body its
// ray hit (PushReport::body_motions).
struct SupervoxelDisplacement {
  std::size_t points = 0;     // the supervoxel's points in the frame before the push
  std::size_t displaced = 0;  // of which moved by more than the motion threshold
  double share() const {
    return points ? static_cast<double>(displaced) / static_cast<double>(points) : 0.0;
  }
  // At least kObjectFraction of the points: the same majority that makes a supervoxel
  // an object makes it moved, so that a mixed supervoxel is judged by what most of it
  // is, and an object turned about its centre of mass (which barely moves) still moved,
  // unless the turn is one its shape and colour hide (a plain ball's: visible_motion.h).
  bool moved() const { return points > 0 && share() >= kObjectFraction; }
};

// The displacement of supervoxel `supervoxel_id` of `maps` (computed on `frame`) by
// `push`. INVALID_ARGUMENT as SupervoxelGroundTruth, or when the push names no motion
// for a body the frame shows.
StatusOr<SupervoxelDisplacement> DisplacementOf(const CameraFrame& frame,
                                                const v1::ComputeMapsResponse& maps,
                                                std::uint32_t supervoxel_id,
                                                const PushReport& push);

}  // namespace relmap::sim
