// A camera frame's pixel (u, v), for the camera tests: its point and the body it saw.
#pragma once

#include <cstddef>
#include <cstdint>

#include "simulated_scene.h"

namespace relmap::sim {

inline const CameraPoint& At(const CameraFrame& frame, int u, int v) {
  return frame.points[static_cast<std::size_t>(v) * frame.width + u];
}
// A point of a temporary frame would dangle once the statement ends (ASan found one).
const CameraPoint& At(CameraFrame&& frame, int u, int v) = delete;

inline std::int32_t IdAt(const CameraFrame& frame, int u, int v) {
  return frame.body_ids[static_cast<std::size_t>(v) * frame.width + u];
}

}  // namespace relmap::sim
