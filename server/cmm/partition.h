// The partition step of SPLIT (§3.6): two groups of a component's samples, from
// the connected components of their 1-nearest-neighbour graph.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "cmm/dataset.h"

namespace relmap::cmm {

// ‖a − b‖² of two p-vectors whose coordinates are `stride_a` and `stride_b`
// apart, summed in coordinate order: every caller gets the same bits for the
// same pair, so nearest neighbours found incrementally and from scratch agree.
double SquaredDistance(const double* a, int stride_a, const double* b, int stride_b, int p);

// The 1-NN graph of the columns of `points`: for each, the index of its nearest
// other column and the squared distance to it (ties: the lower index).
struct NearestNeighbourGraph {
  std::vector<int> nearest;
  std::vector<double> squared_distance;
};
NearestNeighbourGraph NearestNeighbours(const Eigen::MatrixXd& points);

// `points` holds one sample per column and `nearest` its 1-NN graph. Returns, per
// sample, its group (0 or 1), or an empty vector when the graph is connected (no
// split). Group 0 is the one holding the first sample. More than two connected
// components are merged, closest centroids first (Euclidean), until two remain.
// Ties go to the lower index, so the result is deterministic.
std::vector<int> PartitionInTwo(const Eigen::MatrixXd& points, const std::vector<int>& nearest);
// The same for the samples `indices` of `data`, read in place (the same bits): a
// gathered copy per split proposal cost more than the centroids it feeds, the
// allocator mapping fresh pages for each.
std::vector<int> PartitionInTwo(const Dataset& data, std::span<const int> indices,
                                const std::vector<int>& nearest);
inline std::vector<int> PartitionInTwo(const Eigen::MatrixXd& points) {
  return PartitionInTwo(points, NearestNeighbours(points).nearest);
}

}  // namespace relmap::cmm
