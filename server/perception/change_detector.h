// Labelling a push from two clouds (ALGORITHMS.md §5): did the target move?
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"

namespace relmap::perception {

// The label and what it rests on.
struct ChangeEvidence {
  bool moved = false;
  // Before-cloud points in octree cells that are empty after the push, then what is left
  // after the statistical and the radius outlier removal.
  std::size_t difference_points = 0;
  std::size_t after_statistical = 0;
  std::size_t after_radius = 0;
  bool icp_ran = false;
  bool icp_converged = false;
  double icp_fitness = 0;  // m², mean squared nearest distance; meaningful if icp_ran
  double elapsed_ms = 0;
};

// `target_voxels`: positions of the target supervoxel's voxels in the before frame.
StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const std::vector<Eigen::Vector3f>& target_voxels,
                                      const ChangeDetectorConfig& config);

}  // namespace relmap::perception
