// All fixed-radius neighbours of every point of a small cloud, on a uniform grid: the same
// sets as PCL's KdTreeFLANN::radiusSearch, without its per-query allocations.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace relmap::perception {

// FLANN's L2_Simple squared distance, which KdTreeFLANN compares with the radius: diff =
// query - point, squared and summed x, then y, then z, in float.
inline float FlannSquaredDistance(float qx, float qy, float qz, float px, float py, float pz) {
  const float dx = qx - px, dy = qy - py, dz = qz - pz;
  return dx * dx + dy * dy + dz * dz;
}

// A compressed-row neighbour table. Rows are the points in grid order (row r is input point
// `order[r]`), and neighbours are row numbers too, ascending within a row, the point itself
// included: row r's neighbours are neighbour[begin[r]] .. neighbour[begin[r + 1] - 1].
struct RadiusNeighbours {
  std::vector<std::uint32_t> order;
  std::vector<std::size_t> begin;
  std::vector<std::uint32_t> neighbour;
};

// j is a neighbour of i iff FlannSquaredDistance(i, j) is below float(radius²): exactly
// KdTreeFLANN's radiusSearch(point, radius) with unlimited neighbours. The relation is symmetric
// and bitwise equal both ways. Parallel over `threads`.
RadiusNeighbours FindRadiusNeighbours(const std::vector<Eigen::Vector3f>& positions, float radius,
                                      int threads);

}  // namespace relmap::perception
