// Ground truth of a relevance map (ALGORITHMS §6): a supervoxel is part of a moveable
// object when at least half of its points hit a moveable body. The points of a
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

}  // namespace relmap::sim
