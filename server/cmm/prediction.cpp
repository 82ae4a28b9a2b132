// Batched prediction (§3.3) and the nearest-component quantities of exploration
// (§4.2): one pass of the distance kernel per component over all N points.
#include <limits>

#include "cmm/calibration.h"
#include "cmm/collaborative_mixture_models.h"
#include "cmm/log_math.h"
#include "cmm/mixture_density.h"

namespace relmap::cmm {

Evaluation CollaborativeMixtureModels::Evaluate(
    const Eigen::Ref<const Eigen::MatrixXd>& points) const {
  const int n = static_cast<int>(points.rows());
  const int stride = static_cast<int>(points.outerStride());
  Evaluation result;
  result.dimension = dimension();
  result.nearest_squared_mahalanobis =
      Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  Eigen::VectorXd nearest_log_weighted = Eigen::VectorXd::Constant(n, kNegativeInfinity);
  Eigen::VectorXi nearest_class = Eigen::VectorXi::Zero(n);

  std::array<Eigen::VectorXd, 2> log_gamma;
  Eigen::VectorXd squared(n);
  for (int label = 0; label < 2; ++label) {
    const auto& mixture = components_[label];
    Eigen::MatrixXd log_density(n, static_cast<Eigen::Index>(mixture.size()));
    std::vector<WeightedColumn> columns;
    for (int k = 0; k < static_cast<int>(mixture.size()); ++k) {
      const Component& c = mixture[k];
      const double log_weight = std::log(c.weight());
      c.SquaredMahalanobis(points.data(), n, stride, squared.data());
      for (int i = 0; i < n; ++i) {
        log_density(i, k) = c.LogDensityFromSquaredDistance(squared[i]);
        if (squared[i] < result.nearest_squared_mahalanobis[i]) {
          result.nearest_squared_mahalanobis[i] = squared[i];
          nearest_log_weighted[i] = log_weight + log_density(i, k);
          nearest_class[i] = label;
        }
      }
      columns.push_back({{log_density.col(k).data(), static_cast<std::size_t>(n)}, log_weight});
    }
    log_gamma[label] = MixtureLogDensity(columns, n);
  }

  // The pseudo-count: the paper's 1, or the background density B(x).
  Eigen::VectorXd log_pseudo = Eigen::VectorXd::Zero(n);
  if (config_.prediction == Prediction::kCalibrated && prior_.computed_from > 0) {
    prior_.BackgroundLogDensity(points.data(), n, stride, log_pseudo.data());
    log_pseudo.array() += LogPseudoCountWeight();
  }
  result.relevance.resize(n);
  result.nearest_log_membership.resize(n);
  for (int i = 0; i < n; ++i) {
    // Eq. (class_est): P(L=1|x) = (1 + Γ1) / (2 + Γ0 + Γ1), or calibrated
    // ε/2 + (1 − ε)σ(τ log((B/(n+1) + Γ1)/(B/(n+1) + Γ0))); 0.5 with no component.
    result.relevance[i] = std::exp(LogCalibratedProbability(
        LogOdds(log_gamma[1][i], log_gamma[0][i], log_pseudo[i]), calibration_));
    const double class_log_gamma = log_gamma[nearest_class[i]][i];
    result.nearest_log_membership[i] = class_log_gamma == kNegativeInfinity
                                           ? kNegativeInfinity
                                           : nearest_log_weighted[i] - class_log_gamma;
  }
  return result;
}

Eigen::VectorXd CollaborativeMixtureModels::Predict(
    const Eigen::Ref<const Eigen::MatrixXd>& points) const {
  return Evaluate(points).relevance;
}

}  // namespace relmap::cmm
