// The 48-d feature of every supervoxel of a segmentation (docs/method.md §2): one N x 48
// matrix, rows aligned with the supervoxel ids.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "perception/cloud.h"
#include "perception/perception_config.h"
#include "perception/supervoxels.h"

namespace relmap::perception {

inline constexpr int kFeatureDims = 48;

struct FeatureMatrix {
  Eigen::MatrixXd values;  // N x 48: 15 colour values (L, a, b bins), then 33 FPFH values
  // Per row, the number of non-finite values. A row with any must not reach the
  // classifier (§2: relevance 0.5, choice weight 0).
  std::vector<int> non_finite;
  std::size_t non_finite_rows = 0;
};

// `cloud` is the cloud `segmentation` was extracted from (the raw-point FPFH reads it).
FeatureMatrix ComputeFeatures(const Cloud& cloud, const Segmentation& segmentation,
                              const FeatureConfig& config, int threads);

}  // namespace relmap::perception
