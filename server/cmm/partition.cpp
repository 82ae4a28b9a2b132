// Union-find and centroid agglomeration down to two groups (§3.6); the 1-NN graph
// itself is in nearest_neighbours.cpp.
#include "cmm/partition.h"

#include <limits>
#include <numeric>

namespace relmap::cmm {
namespace {

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int Find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  // The lower root survives, so roots are the smallest member of their set.
  void Join(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
  }

 private:
  std::vector<int> parent_;
};

// Column j of a set of p-vectors: its first coordinate and the distance between
// its coordinates (1 in a gathered matrix, the stride of a Dataset in place).
struct PointView {
  const double* first;
  int stride;
};

// Agglomerates groups by closest centroids until two remain. `group` maps each
// sample to a group id in [0, groups); returns the surviving group of each id.
// `point(i)` is sample i's PointView.
template <typename Points>
std::vector<int> MergeClosestCentroids(const Points& point, int p, const std::vector<int>& group,
                                       int groups) {
  Eigen::MatrixXd centroid = Eigen::MatrixXd::Zero(p, groups);
  std::vector<double> count(groups, 0.0);
  for (int i = 0; i < static_cast<int>(group.size()); ++i) {
    const PointView x = point(i);
    centroid.col(group[i]) += Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>(
        x.first, p, Eigen::InnerStride<>(x.stride));
    count[group[i]] += 1.0;
  }
  for (int g = 0; g < groups; ++g) centroid.col(g) /= count[g];

  std::vector<int> survivor(groups);
  std::iota(survivor.begin(), survivor.end(), 0);
  std::vector<bool> active(groups, true);
  // ‖c_g − c_h‖² of every pair, kept at [g·groups + h] for g < h and recomputed
  // only for the merged centroid: a group that loses its partner scans this row
  // instead of recomputing G distances of p coordinates (the same values, so
  // the same merges).
  std::vector<double> pair(static_cast<std::size_t>(groups) * static_cast<std::size_t>(groups));
  const auto at = [&](int g, int h) -> double& {
    return pair[static_cast<std::size_t>(g) * static_cast<std::size_t>(groups) +
                static_cast<std::size_t>(h)];
  };
  for (int g = 0; g < groups; ++g) {
    for (int h = g + 1; h < groups; ++h)
      at(g, h) = (centroid.col(g) - centroid.col(h)).squaredNorm();
  }
  // Each active group's closest active partner with a higher id; a pair is kept
  // once, at its lower id, which makes ties resolve to the lowest pair.
  std::vector<int> partner(groups, -1);
  std::vector<double> distance(groups, std::numeric_limits<double>::infinity());
  auto refresh = [&](int g) {
    partner[g] = -1;
    distance[g] = std::numeric_limits<double>::infinity();
    for (int h = g + 1; h < groups; ++h) {
      if (!active[h]) continue;
      const double d = at(g, h);
      if (d < distance[g]) distance[g] = d, partner[g] = h;
    }
  };
  for (int g = 0; g < groups; ++g) refresh(g);

  for (int remaining = groups; remaining > 2; --remaining) {
    int a = -1;
    for (int g = 0; g < groups; ++g) {
      if (active[g] && partner[g] >= 0 && (a < 0 || distance[g] < distance[a])) a = g;
    }
    const int b = partner[a];
    centroid.col(a) =
        (centroid.col(a) * count[a] + centroid.col(b) * count[b]) / (count[a] + count[b]);
    count[a] += count[b];
    active[b] = false;
    for (int g = 0; g < groups; ++g) {
      if (survivor[g] == b) survivor[g] = a;
    }
    for (int g = 0; g < groups; ++g) {
      if (!active[g] || g == a) continue;
      if (g < a) {
        at(g, a) = (centroid.col(g) - centroid.col(a)).squaredNorm();
      } else {
        at(a, g) = (centroid.col(a) - centroid.col(g)).squaredNorm();
      }
    }
    // Groups below `a` may now be closest to the moved centroid of `a`; groups
    // that pointed at `a` or `b` must look again.
    for (int g = 0; g < groups; ++g) {
      if (!active[g] || g == a) continue;
      if (partner[g] == a || partner[g] == b) {
        refresh(g);
      } else if (g < a) {
        const double d = at(g, a);
        if (d < distance[g] || (d == distance[g] && a < partner[g]))
          distance[g] = d, partner[g] = a;
      }
    }
    refresh(a);
  }
  return survivor;
}

}  // namespace

double SquaredDistance(const double* a, int stride_a, const double* b, int stride_b, int p) {
  double sum = 0.0;
  for (int k = 0; k < p; ++k) {
    const double d =
        a[static_cast<std::ptrdiff_t>(k) * stride_a] - b[static_cast<std::ptrdiff_t>(k) * stride_b];
    sum += d * d;
  }
  return sum;
}

namespace {

template <typename Points>
std::vector<int> PartitionInTwoOf(const Points& point, int n, int p,
                                  const std::vector<int>& nearest) {
  if (n < 2) return {};
  UnionFind sets(n);
  for (int i = 0; i < n; ++i) sets.Join(i, nearest[i]);

  // Number the sets by their smallest member: sample 0 is in set 0.
  std::vector<int> set_of_root(n, -1);
  std::vector<int> group(n);
  int groups = 0;
  for (int i = 0; i < n; ++i) {
    const int root = sets.Find(i);
    if (set_of_root[root] < 0) set_of_root[root] = groups++;
    group[i] = set_of_root[root];
  }
  if (groups == 1) return {};
  if (groups > 2) {
    const std::vector<int> survivor = MergeClosestCentroids(point, p, group, groups);
    // Set 0 always survives (a merge keeps the lower id); the other survivor is group 1.
    for (int& g : group) g = survivor[g] == 0 ? 0 : 1;
  }
  return group;
}

}  // namespace

std::vector<int> PartitionInTwo(const Eigen::MatrixXd& points, const std::vector<int>& nearest) {
  const int p = static_cast<int>(points.rows());
  return PartitionInTwoOf(
      [&](int j) {
        return PointView{points.col(j).data(), 1};
      },
      static_cast<int>(points.cols()), p, nearest);
}

std::vector<int> PartitionInTwo(const Dataset& data, std::span<const int> indices,
                                const std::vector<int>& nearest) {
  return PartitionInTwoOf(
      [&](int j) {
        return PointView{data.data() + indices[j], data.stride()};
      },
      static_cast<int>(indices.size()), data.dimension(), nearest);
}

}  // namespace relmap::cmm
