// Labelling a push from two clouds (docs/method.md §5): did the target move?
#pragma once

#include <cstddef>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"
#include "perception/supervoxels.h"

namespace relmap::perception {

// The label and what it rests on.
struct ChangeEvidence {
  bool moved = false;
  ChangeMethod method = ChangeMethod::kVisibility;

  // kVisibility: the target's finite before-points, and how many of them the after frame
  // shows still there, seen through (vacated) or hidden behind something nearer (occluded);
  // the rest fall on holes of the after frame and say nothing.
  std::size_t target_points = 0;
  std::size_t supported_points = 0;
  std::size_t vacated_points = 0;
  std::size_t occluded_points = 0;
  // The camera motion between the frames that was compensated first.
  double camera_rotation_deg = 0;
  double camera_translation_m = 0;

  // kPaper2018: before-cloud points in octree cells that are empty after the push, then
  // what is left after the statistical and the radius outlier removal, and the ICP.
  std::size_t difference_points = 0;
  std::size_t after_statistical = 0;
  std::size_t after_radius = 0;
  bool icp_ran = false;
  bool icp_converged = false;
  double icp_fitness = 0;  // m², mean squared nearest distance; meaningful if icp_ran

  double elapsed_ms = 0;
};

// `target` is a supervoxel of `before` (its points and voxels index and lie in `before`).
StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const Supervoxel& target, const ChangeDetectorConfig& config);

}  // namespace relmap::perception
