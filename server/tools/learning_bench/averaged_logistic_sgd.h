// Online logistic regression by averaged SGD (Polyak & Juditsky, 1992): one
// stochastic gradient step per sample, predictions from the running average of
// the iterates, on inputs standardised with running means and deviations.
#pragma once

#include "learning_bench/online_learner.h"
#include "learning_bench/running_moments.h"

namespace relmap::learning_bench {

class AveragedLogisticSgd final : public OnlineLearner {
 public:
  explicit AveragedLogisticSgd(int dimension);

  Status Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) override;
  Eigen::VectorXd Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const override;
  std::string Name() const override { return "sgd"; }

 private:
  // (x − mean) / deviation with the statistics seen so far; 0 in a dimension
  // that has not varied yet.
  Eigen::VectorXd Standardise(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  RunningMoments inputs_;
  Eigen::VectorXd w_, w_average_;  // weights on standardised inputs
  double b_ = 0.0, b_average_ = 0.0;
  long steps_ = 0;
};

}  // namespace relmap::learning_bench
