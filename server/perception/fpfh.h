// The 33 FPFH values of each supervoxel's feature (docs/method.md §2), in three schemes: the
// exact per-union computation, the shared per-voxel one and the per-raw-point one
// (perception_config.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "perception/cloud.h"
#include "perception/pair_features.h"
#include "perception/perception_config.h"
#include "perception/supervoxels.h"

namespace relmap::perception {

// PCL's FPFH (FPFHEstimation) at every point of a cloud with itself as search surface,
// divided by 100 so that each 11-bin block sums to 1 (a point with no neighbour in `radius`
// has an all-zero row). One grid radius search, one pair computation per pair of
// neighbours and one SPFH per point, parallel over `threads`. Rows follow `positions`;
// normals must be finite.
Eigen::MatrixXf PointFpfh(const std::vector<Eigen::Vector3f>& positions,
                          const std::vector<Eigen::Vector3f>& normals, float radius, int threads);

// N x 33: per supervoxel, the mean of the point FPFH (divided by 100) over the points of the
// supervoxel and of its neighbours, the points being voxels or raw points by `config`'s
// scheme; `cloud` is the cloud `segmentation` was extracted from. Points whose VCCS normal
// is not finite (a voxel with fewer than three voxels around it) are left out; a supervoxel
// whose union has none left gets a NaN row, which the frame counts as non-finite.
Eigen::MatrixXd SupervoxelFpfh(const Cloud& cloud, const Segmentation& segmentation,
                               const FeatureConfig& config, int threads);

// The three schemes behind SupervoxelFpfh.
Eigen::MatrixXd SupervoxelFpfhExactUnion(const Segmentation& segmentation, float radius,
                                         int threads);
Eigen::MatrixXd SupervoxelFpfhSharedVoxels(const Segmentation& segmentation, float radius,
                                           int threads);
Eigen::MatrixXd SupervoxelFpfhRawPoints(const Cloud& cloud, const Segmentation& segmentation,
                                        const FeatureConfig& config, int threads);

// The voxels of `supervoxel` and its neighbours with a finite normal.
void CollectUnionVoxels(const Segmentation& segmentation, const Supervoxel& supervoxel,
                        std::vector<Eigen::Vector3f>& positions,
                        std::vector<Eigen::Vector3f>& normals);

}  // namespace relmap::perception
