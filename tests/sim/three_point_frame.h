// A camera frame of three points, for the packed-cloud tests of the simulator and of
// its contract with the server's decoder: two points on bodies 1 and 0, a hole between.
#pragma once

#include <limits>

#include "simulated_scene.h"

namespace relmap::sim {

inline CameraFrame ThreePoints() {
  CameraFrame frame;
  frame.width = 3;
  frame.height = 1;
  frame.points = {{0.25f, -0.5f, 1.0f, 10, 20, 30},
                  {std::numeric_limits<float>::quiet_NaN(), 0, 0, 1, 2, 3},
                  {-1.5f, 2.0f, 3.75f, 255, 0, 128}};
  frame.body_ids = {1, kNoBody, 0};
  return frame;
}

}  // namespace relmap::sim
