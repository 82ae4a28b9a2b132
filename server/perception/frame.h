// A Frame: one decoded cloud turned into supervoxels and their features, the unit the
// session layer caches and that outcomes refer to as (frame_id, supervoxel_id).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/features.h"
#include "perception/perception_config.h"
#include "perception/supervoxels.h"

namespace relmap::perception {

// Milliseconds per stage, for logs and the benchmarks.
struct FrameTimings {
  double filter_ms = 0;       // finite points, crop box, pre-voxelisation
  double supervoxels_ms = 0;  // VCCS, including its voxel normals
  double normals_ms = 0;      // taking over VCCS's output and voxel normals
  double features_ms = 0;     // colour histograms and FPFH
  double total_ms = 0;
};

struct Frame {
  Cloud cloud;
  // supervoxels[i].id == i == row i of features.values; point_labels per cloud point.
  Segmentation segmentation;
  FeatureMatrix features;
  // Per supervoxel, the object it lies on (change_object.h ObjectLabels, with
  // config.change.object_smooth_angle_deg): one value per rigid object a push moves whole.
  std::vector<std::uint32_t> objects;
  FrameTimings timings;

  std::size_t size() const { return segmentation.supervoxels.size(); }
};

// The one entry point from a decoded cloud to a Frame. Validates `config` first.
StatusOr<Frame> BuildFrame(Cloud cloud, const PerceptionConfig& config);

}  // namespace relmap::perception
