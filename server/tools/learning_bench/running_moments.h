// Per-dimension running mean and variance (Welford's update), shared by the
// benchmark's naive Bayes and its input standardisation.
#pragma once

#include <Eigen/Core>

namespace relmap::learning_bench {

class RunningMoments {
 public:
  explicit RunningMoments(int dimension)
      : mean_(Eigen::VectorXd::Zero(dimension)), squares_(Eigen::VectorXd::Zero(dimension)) {}

  // Welford: numerically stable in one pass, unlike Σx² − n·mean².
  void Add(const Eigen::Ref<const Eigen::VectorXd>& x) {
    ++count_;
    const Eigen::VectorXd before = x - mean_;
    mean_ += before / static_cast<double>(count_);
    squares_ += before.cwiseProduct(x - mean_);
  }

  long count() const { return count_; }
  const Eigen::VectorXd& mean() const { return mean_; }
  // The maximum-likelihood variance Σ(x − mean)²/n; zero before two samples.
  Eigen::VectorXd variance() const {
    return count_ == 0 ? squares_ : Eigen::VectorXd(squares_ / static_cast<double>(count_));
  }

 private:
  long count_ = 0;
  Eigen::VectorXd mean_;
  Eigen::VectorXd squares_;  // Σ (x − mean)², Welford's M2
};

}  // namespace relmap::learning_bench
