// A frame's maps for RViz: one PointCloud2 per map over the points that were sent, and
// the drawn target as a pose.
#pragma once

#include <optional>

#include "cloud_message.h"
#include "common/pcd/pcd_reader.h"
#include "common/status.h"
#include "map_rendering.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::ros_bridge {

// The points of `sent` that lie in a supervoxel of `maps`, unorganized, with fields x,
// y, z, rgb (the colours of the paper's figures, client::ColourPoints: relevance black →
// yellow, choice blue → red, the target's border green), intensity (the point's
// supervoxel's relevance, or its choice probability) and supervoxel (its id, uint32,
// as ~post_outcome takes it). INVALID_ARGUMENT when `maps` does not label `sent`.
StatusOr<CloudMessage> MapCloud(const pcd::Points& sent, const v1::ComputeMapsResponse& maps,
                                client::MapKind kind, const std::string& frame_id, Stamp stamp);

// The target `maps` drew, as a pose in `frame_id`: nullopt when there is none.
std::optional<TargetPose> TargetOf(const v1::ComputeMapsResponse& maps, const std::string& frame_id,
                                   Stamp stamp);

// The rotation taking the x axis onto `direction` (normalised here; the identity for a
// zero vector, a half turn about z for the opposite of x).
Quaternion RotationFromXAxis(Vector3d direction);

}  // namespace relmap::ros_bridge
