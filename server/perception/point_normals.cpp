// PCA normals on the grid radius search of radius_neighbours.h.
#include "perception/point_normals.h"

#include <Eigen/Eigenvalues>
#include <cstddef>
#include <limits>

#include "perception/radius_neighbours.h"

namespace relmap::perception {

std::vector<Eigen::Vector3f> EstimateNormals(const std::vector<Eigen::Vector3f>& positions,
                                             float radius, int threads) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Eigen::Vector3f> normals(positions.size(), Eigen::Vector3f::Constant(nan));
  if (positions.empty()) return normals;
  const RadiusNeighbours table = FindRadiusNeighbours(positions, radius, threads);
  const auto n = static_cast<std::ptrdiff_t>(positions.size());
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::ptrdiff_t r = 0; r < n; ++r) {
    const auto ur = static_cast<std::size_t>(r);
    const std::size_t k = table.begin[ur + 1] - table.begin[ur];
    if (k < 3) continue;
    // Covariance in double about the mean: raw points are millimetres apart metres away
    // from the camera, where float sums of squares lose the normal direction.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t e = table.begin[ur]; e < table.begin[ur + 1]; ++e) {
      mean += positions[table.order[table.neighbour[e]]].cast<double>();
    }
    mean /= static_cast<double>(k);
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::size_t e = table.begin[ur]; e < table.begin[ur + 1]; ++e) {
      const Eigen::Vector3d d = positions[table.order[table.neighbour[e]]].cast<double>() - mean;
      covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    Eigen::Vector3f normal = eigen.eigenvectors().col(0).cast<float>();  // smallest eigenvalue
    const Eigen::Vector3f& p = positions[table.order[ur]];
    if (normal.dot(-p) < 0.0f) normal = -normal;  // PCL's flipNormalTowardsViewpoint, vp = 0
    normals[table.order[ur]] = normal;
  }
  return normals;
}

}  // namespace relmap::perception
