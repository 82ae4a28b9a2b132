// Online Gaussian naive Bayes: one axis-aligned Gaussian per class, its mean
// and variance updated with each sample.
#pragma once

#include <array>

#include "learning_bench/online_learner.h"
#include "learning_bench/running_moments.h"

namespace relmap::learning_bench {

class GaussianNaiveBayes final : public OnlineLearner {
 public:
  explicit GaussianNaiveBayes(int dimension)
      : classes_{RunningMoments(dimension), RunningMoments(dimension)}, all_(dimension) {}

  Status Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) override;
  Eigen::VectorXd Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const override;
  std::string Name() const override { return "gnb"; }

 private:
  std::array<RunningMoments, 2> classes_;
  RunningMoments all_;  // every sample regardless of class: the feature scale
};

}  // namespace relmap::learning_bench
