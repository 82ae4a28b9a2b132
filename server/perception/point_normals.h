// Normals of a point cloud by PCA of each point's fixed-radius neighbourhood, as PCL's
// NormalEstimation computes them, without PCL types.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace relmap::perception {

// Per point: the eigenvector of the smallest eigenvalue of the covariance of the points
// within `radius` (the point included), oriented towards the camera at the origin. NaN for a
// point with fewer than 3 such points (PCL's answer too). Parallel over `threads`.
std::vector<Eigen::Vector3f> EstimateNormals(const std::vector<Eigen::Vector3f>& positions,
                                             float radius, int threads);

}  // namespace relmap::perception
