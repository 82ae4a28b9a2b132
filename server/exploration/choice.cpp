// Confidence, choice map and target sampling.
#include "exploration/choice.h"

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <cassert>
#include <cmath>

#include "exploration/uncertainty.h"

namespace relmap::exploration {

Eigen::VectorXd Confidence(const cmm::Evaluation& evaluation, ConfidenceMode mode) {
  if (mode == ConfidenceMode::kMembership) return evaluation.nearest_log_membership.array().exp();
  if (mode == ConfidenceMode::kChiSquare) {
    // Q(p/2, d²/2), the χ²_p survival function; 0 with no component (d² = +∞).
    const double half_p = 0.5 * evaluation.dimension;
    return evaluation.nearest_squared_mahalanobis.unaryExpr([half_p](double d2) {
      return std::isfinite(d2) ? boost::math::gamma_q(half_p, 0.5 * std::max(d2, 0.0)) : 0.0;
    });
  }
  // c = exp(−½ d²) of the nearest component: 1 at its mean, 0 far from all data
  // (and with no component at all, d² = +∞).
  return (-0.5 * evaluation.nearest_squared_mahalanobis.array()).exp();
}

Eigen::VectorXd UncertaintyMap(const Eigen::VectorXd& relevance, int moveable_samples,
                               int non_moveable_samples, bool uncertainty_bug) {
  Eigen::VectorXd u(relevance.size());
  for (Eigen::Index i = 0; i < relevance.size(); ++i) {
    u[i] = Uncertainty(relevance[i], moveable_samples, non_moveable_samples, uncertainty_bug);
  }
  return u;
}

Eigen::VectorXd ChoiceMap(const Eigen::VectorXd& uncertainty, const Eigen::VectorXd& confidence,
                          bool paper_quirks) {
  const Eigen::VectorXd unknown = Eigen::VectorXd::Constant(uncertainty.size(), 0.5);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(uncertainty.size());
  return ChoiceMap({unknown, uncertainty, confidence, ones},
                   ExplorationConfig{.paper_choice_quirks = paper_quirks});
}

namespace {

// ½ g/Σ_P g on P = {i : r_i ≥ ½}, the supervoxels predicted moveable, and ½ g/Σ_N g on
// the rest; a class with no weight is left out and the other takes all. Split by the
// prediction, not in proportion to r: in a scene of one moveable supervoxel to ten of
// background, draws in proportion to a soft r still land mostly on background.
Eigen::VectorXd HalfPerPredictedClass(const Eigen::VectorXd& relevance, const Eigen::VectorXd& g) {
  Eigen::VectorXd moveable = (relevance.array() >= 0.5).select(g, 0.0);
  Eigen::VectorXd background = g - moveable;
  const double sm = moveable.sum(), sb = background.sum();
  if (!(sm > 0.0)) return background;
  if (!(sb > 0.0)) return moveable;
  return 0.5 * (moveable / sm + background / sb);
}

}  // namespace

Eigen::VectorXd ChoiceMap(const ChoiceTerms& terms, const ExplorationConfig& config) {
  const Eigen::VectorXd& g = terms.novelty;
  assert(terms.uncertainty.size() == terms.confidence.size() &&
         g.size() == terms.confidence.size() && terms.relevance.size() == g.size());
  const bool paper_quirks = config.paper_choice_quirks;
  Eigen::VectorXd w = config.rule == ChoiceRule::kClassBalanced
                          ? HalfPerPredictedClass(terms.relevance, g)
                          : Eigen::VectorXd(terms.uncertainty.array() *
                                            (1.0 - terms.confidence.array()) * g.array());
  if (paper_quirks) w = (w.array() < kPaperChoiceFloor).select(0.0, w);
  const double total = w.sum();
  if (!(total > 0.0)) {
    return Eigen::VectorXd::Constant(
        w.size(), 1.0 / static_cast<double>(std::max<Eigen::Index>(1, w.size())));
  }
  const double share = config.random_share;
  if (share <= 0.0) return w / total;
  return (1.0 - share) * (w / total).array() + share / static_cast<double>(w.size());
}

int DrawTarget(const Eigen::VectorXd& choice, int interactions, bool paper_quirks, Random& random) {
  const auto n = static_cast<std::size_t>(choice.size());
  assert(n > 0);
  if (paper_quirks && interactions < kPaperUniformChoices) {
    return static_cast<int>(random.UniformIndex(n > 1 ? n - 1 : 1));
  }
  // Inverse transform sampling on the cumulative sums.
  const double u = random.UniformUnit() * choice.sum();
  double cumulative = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    cumulative += choice[static_cast<Eigen::Index>(i)];
    if (u < cumulative) return static_cast<int>(i);
  }
  // Rounding left u at the very top: the last index with positive weight.
  for (std::size_t i = n; i-- > 0;) {
    if (choice[static_cast<Eigen::Index>(i)] > 0.0) return static_cast<int>(i);
  }
  return static_cast<int>(n - 1);
}

}  // namespace relmap::exploration
