// P(1|x) = σ(log N(x; μ1, v1) − log N(x; μ0, v0)) with diagonal variances,
// summed over dimensions in the log domain (48 densities would underflow).
#include "learning_bench/gaussian_naive_bayes.h"

#include <cmath>
#include <numbers>

#include "learning_bench/sigmoid.h"

namespace relmap::learning_bench {
namespace {

// Variance floor: a fraction of the mean per-dimension variance of all samples,
// so that it scales with the features (like sklearn's var_smoothing, but relative
// to the mean rather than the maximum, which one wide dimension would dominate),
// plus an absolute epsilon for when every sample seen is the same point.
constexpr double kRelativeFloor = 1e-3;
constexpr double kAbsoluteFloor = 1e-12;

}  // namespace

Status GaussianNaiveBayes::Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) {
  if (Status s = CheckSample(Name(), x, label, all_.mean().size()); !s.ok()) return s;
  classes_[label].Add(x);
  all_.Add(x);
  return OkStatus();
}

Eigen::VectorXd GaussianNaiveBayes::Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const {
  Eigen::VectorXd p = Eigen::VectorXd::Constant(points.rows(), 0.5);
  // With a class unseen there is no likelihood ratio: say nothing.
  if (classes_[0].count() == 0 || classes_[1].count() == 0) return p;
  const double floor = kRelativeFloor * all_.variance().mean() + kAbsoluteFloor;
  std::array<Eigen::ArrayXd, 2> inverse_variance, log_normaliser;
  for (int c = 0; c < 2; ++c) {
    const Eigen::ArrayXd v = classes_[c].variance().array() + floor;
    inverse_variance[c] = v.inverse();
    log_normaliser[c] = -0.5 * (2.0 * std::numbers::pi * v).log();
  }
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    double log_ratio = 0.0;  // log N(x|1) − log N(x|0)
    for (int c = 0; c < 2; ++c) {
      const Eigen::ArrayXd d = points.row(i).transpose().array() - classes_[c].mean().array();
      const double log_density = (log_normaliser[c] - 0.5 * d.square() * inverse_variance[c]).sum();
      log_ratio += c == 1 ? log_density : -log_density;
    }
    // Equal class priors, not the counts: the class balance of a stream is set
    // by whoever chose what to label (the exploration, a flipped label), not by
    // the scene; and equal priors are the Bayes rule for balanced accuracy, the
    // benchmark's headline metric.
    p[i] = Sigmoid(log_ratio);
  }
  return p;
}

}  // namespace relmap::learning_bench
