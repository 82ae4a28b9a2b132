// The 1-NN graph of SPLIT (§3.6) from scratch: every pair's squared distance,
// summed in coordinate order as SquaredDistance does, so the graph is the one
// an incremental update (Component::AddToNearestNeighbours) keeps.
#include <limits>
#include <vector>

#include "cmm/partition.h"

namespace relmap::cmm {

NearestNeighbourGraph NearestNeighbours(const Eigen::MatrixXd& points) {
  const int p = static_cast<int>(points.rows());
  const int n = static_cast<int>(points.cols());
  NearestNeighbourGraph graph{std::vector<int>(n, -1),
                              std::vector<double>(n, std::numeric_limits<double>::infinity())};
  // One coordinate of every point contiguous: the distances from point i to all
  // later points go a coordinate at a time over the whole row, so the compiler
  // vectorises across points while each pair still sums its squares in order
  // 0..p−1 (no contraction into FMA: this file is built for generic x86-64).
  const Eigen::MatrixXd by_coordinate = points.transpose();
  std::vector<double> sum(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int first = i + 1;
    std::fill(sum.begin() + first, sum.end(), 0.0);
    for (int k = 0; k < p; ++k) {
      const double* coordinate = by_coordinate.col(k).data();
      const double x = coordinate[i];
      for (int j = first; j < n; ++j) {
        const double d = coordinate[j] - x;
        sum[static_cast<std::size_t>(j)] += d * d;
      }
    }
    for (int j = first; j < n; ++j) {
      const double d = sum[static_cast<std::size_t>(j)];
      if (d < graph.squared_distance[i]) graph.squared_distance[i] = d, graph.nearest[i] = j;
      if (d < graph.squared_distance[j]) graph.squared_distance[j] = d, graph.nearest[j] = i;
    }
  }
  return graph;
}

}  // namespace relmap::cmm
