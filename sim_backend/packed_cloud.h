// A simulated camera frame as the API's packed cloud (PackedCloud in
// relevance_service.proto): per point float32 x, y, z then uint8 r, g, b, a, 16 bytes,
// little endian, row-major, holes as NaN coordinates.
#pragma once

#include "relmap/v1/relevance_service.pb.h"
#include "simulated_scene.h"

namespace relmap::sim {

inline constexpr std::size_t kPackedPointBytes = 16;

// The frame's points, organized as captured; every point opaque (a = 255).
v1::Cloud PackCloud(const CameraFrame& frame);

}  // namespace relmap::sim
