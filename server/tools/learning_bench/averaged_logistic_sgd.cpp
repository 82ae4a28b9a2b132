// Step t (from 0) on the loss log(1 + e^−y·f) + ½λ‖w‖², y ∈ {−1, 1}, then the
// running averages w̄ ← w̄ + (w − w̄)/(t + 1).
#include "learning_bench/averaged_logistic_sgd.h"

#include <cmath>

#include "learning_bench/sigmoid.h"

namespace relmap::learning_bench {
namespace {

// L2 weight: small, only to keep the weights finite on separable streams.
constexpr double kLambda = 1e-4;
// A standardised input has E‖z‖² ≈ p, so a step of η changes the sample's own
// log-odds by about η·p·|gradient| ≤ η·p: η₀ = 1/p keeps that at most 1.
// η_t = η₀/√(1 + t) decays slower than 1/t, the regime in which averaging gives
// the optimal rate without tuning η₀ to the curvature (Polyak & Juditsky).
double LearningRate(long t, Eigen::Index p) {
  return 1.0 / (static_cast<double>(p) * std::sqrt(1.0 + static_cast<double>(t)));
}

}  // namespace

AveragedLogisticSgd::AveragedLogisticSgd(int dimension)
    : inputs_(dimension),
      w_(Eigen::VectorXd::Zero(dimension)),
      w_average_(Eigen::VectorXd::Zero(dimension)) {}

Eigen::VectorXd AveragedLogisticSgd::Standardise(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Eigen::ArrayXd deviation = inputs_.variance().array().sqrt();
  return ((x - inputs_.mean()).array() / deviation).unaryExpr([](double v) {
    return std::isfinite(v) ? v : 0.0;  // 0/0 in a dimension that never varied
  });
}

Status AveragedLogisticSgd::Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) {
  if (Status s = CheckSample(Name(), x, label, w_.size()); !s.ok()) return s;
  inputs_.Add(x);
  const Eigen::VectorXd z = Standardise(x);
  const double y = label == 1 ? 1.0 : -1.0;
  // d/df log(1 + e^−y·f) = −y·σ(−y·f).
  const double gradient = -y * Sigmoid(-y * (w_.dot(z) + b_));
  const double eta = LearningRate(steps_, w_.size());
  w_ -= eta * (gradient * z + kLambda * w_);
  b_ -= eta * gradient;
  ++steps_;
  w_average_ += (w_ - w_average_) / static_cast<double>(steps_);
  b_average_ += (b_ - b_average_) / static_cast<double>(steps_);
  return OkStatus();
}

Eigen::VectorXd AveragedLogisticSgd::Predict(
    const Eigen::Ref<const Eigen::MatrixXd>& points) const {
  Eigen::VectorXd p(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    p[i] = Sigmoid(w_average_.dot(Standardise(points.row(i).transpose())) + b_average_);
  }
  return p;
}

}  // namespace relmap::learning_bench
