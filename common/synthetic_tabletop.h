// A synthetic organized RGB-D cloud for tests, benchmarks and the tools: a pinhole camera
// looking down at a table with boxes and spheres of distinct colours, with the object id
// of every point known. Plain points, so that clients (relmap-load) make it without the
// server; perception/synthetic_tabletop.h gives it as the server's Cloud.
#pragma once

#include <cstdint>
#include <vector>

#include "common/pcd/point.h"

namespace relmap::synthetic {

struct TabletopOptions {
  std::uint32_t width = 640;  // the focal length scales with the width (525 px at 640)
  std::uint32_t height = 480;
  float camera_height = 0.7f;   // above the table, m
  float camera_pitch_deg = 45;  // downwards
  float depth_noise = 0.001f;   // σ of the depth noise at 1 m, growing with z²
  std::uint32_t seed = 1;
};

struct Tabletop {
  std::uint32_t width = 0, height = 0;
  std::vector<pcd::Point> points;  // row-major, holes NaN
  // Per point: -1 hole (no surface within 3 m), 0 table, k >= 1 the k-th object.
  std::vector<int> object_of_point;
  int objects = 0;
};

Tabletop MakeTabletop(const TabletopOptions& options = {});

}  // namespace relmap::synthetic
