// A linear scan per query: with a few hundred samples it is faster than
// maintaining a tree under insertion.
#include "learning_bench/nearest_neighbours.h"

#include <algorithm>
#include <utility>

namespace relmap::learning_bench {

Status NearestNeighbours::Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) {
  if (Status s = CheckSample(Name(), x, label, dimension_); !s.ok()) return s;
  samples_.emplace_back(x);
  labels_.push_back(label);
  return OkStatus();
}

Eigen::VectorXd NearestNeighbours::Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const {
  Eigen::VectorXd p = Eigen::VectorXd::Constant(points.rows(), 0.5);
  const std::size_t n = std::min(samples_.size(), static_cast<std::size_t>(k_));
  if (n == 0) return p;
  std::vector<std::pair<double, int>> distances(samples_.size());  // (squared distance, label)
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    for (std::size_t j = 0; j < samples_.size(); ++j) {
      distances[j] = {(points.row(i).transpose() - samples_[j]).squaredNorm(), labels_[j]};
    }
    // The pairs order ties in distance by label, so the k nearest are one set
    // of (distance, label) whatever the implementation of nth_element.
    std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(n - 1),
                     distances.end());
    int moveable = 0;
    for (std::size_t j = 0; j < n; ++j) moveable += distances[j].second;
    p[i] = (moveable + 0.5) / (static_cast<double>(n) + 1.0);
  }
  return p;
}

}  // namespace relmap::learning_bench
