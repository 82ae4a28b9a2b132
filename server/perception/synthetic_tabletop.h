// A synthetic organized RGB-D cloud for tests, benchmarks and the tool: a pinhole camera
// looking down at a table with boxes and spheres of distinct colours, with the object id
// of every point known.
#pragma once

#include <cstdint>
#include <vector>

#include "perception/cloud.h"

namespace relmap::perception {

struct SyntheticTabletopOptions {
  std::uint32_t width = 640;  // the focal length scales with the width (525 px at 640)
  std::uint32_t height = 480;
  float camera_height = 0.7f;   // above the table, m
  float camera_pitch_deg = 45;  // downwards
  float depth_noise = 0.001f;   // σ of the depth noise at 1 m, growing with z²
  std::uint32_t seed = 1;
};

struct SyntheticTabletop {
  Cloud cloud;
  // Per point: -1 hole (no surface within 3 m), 0 table, k >= 1 the k-th object.
  std::vector<int> object_of_point;
  int objects = 0;
};

SyntheticTabletop MakeSyntheticTabletop(const SyntheticTabletopOptions& options = {});

}  // namespace relmap::perception
