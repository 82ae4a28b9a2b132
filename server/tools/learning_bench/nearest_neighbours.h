// k-nearest neighbours on the raw features (Euclidean): the memory-based
// reference a mixture model should at least match on a few hundred samples.
#pragma once

#include <vector>

#include "learning_bench/online_learner.h"

namespace relmap::learning_bench {

class NearestNeighbours final : public OnlineLearner {
 public:
  explicit NearestNeighbours(int dimension, int k = 5) : dimension_(dimension), k_(k) {}

  Status Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) override;
  // (m + ½)/(n + 1) for m moveable among the n = min(k, samples) nearest: the
  // smoothing keeps P away from 0 and 1, so that the log-loss stays finite.
  Eigen::VectorXd Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const override;
  std::string Name() const override { return "knn"; }

 private:
  int dimension_;
  int k_;
  std::vector<Eigen::VectorXd> samples_;
  std::vector<int> labels_;
};

}  // namespace relmap::learning_bench
