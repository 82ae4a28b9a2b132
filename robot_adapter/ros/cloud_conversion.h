// sensor_msgs/PointCloud2 (as CloudMessage) to and from plain points, and plain points
// as the API's packed cloud. The server needs x, y, z and a colour: a cloud without
// them is refused here, with a message naming what is missing, before any call.
#pragma once

#include "cloud_message.h"
#include "common/pcd/pcd_reader.h"
#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::ros_bridge {

// The points of `cloud`, organized as it is (width × height, row-major): fields x, y, z
// (float32 or float64) and rgb or rgba (float32 or uint32 holding 0xAARRGGBB, as PCL
// and RViz write them); other fields are skipped, non-finite coordinates are holes.
// INVALID_ARGUMENT for a big-endian cloud, a missing or mistyped field, or a size that
// does not add up.
StatusOr<pcd::Points> DecodeCloudMessage(const CloudMessage& cloud);

// Moves every point but the holes by `transform`.
void TransformPoints(const RigidTransform& transform, pcd::Points* points);

// The points in the API's packed layout (PackedCloud), organized as they are.
v1::Cloud PackPoints(const pcd::Points& points);

// A PointCloud2 of `points` with fields x, y, z (float32) and rgb (float32 bits
// 0x00RRGGBB), organized as they are.
CloudMessage EncodeCloudMessage(const pcd::Points& points, const std::string& frame_id,
                                Stamp stamp);

}  // namespace relmap::ros_bridge
