// Scores of a relevance map against ground truth (§6): the paper's soft metric,
// the thresholded-soft metric behind the authors' published numbers, and the
// usual classifier scores (balanced accuracy, log-loss, Brier) for benchmarks.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace relmap::metrics {

// A ratio whose denominator was 0 is undefined (nullopt), never a number.
struct Scores {
  std::optional<double> precision;
  std::optional<double> recall;
  std::optional<double> accuracy;
};

// `relevance` is P(L=1|x_i); `moveable[i]` is the ground truth (δ_i = 0 for a
// moveable object, 1 for background). Soft (eq. pra/tptn): tp = Σ P1(1−δ),
// tn = Σ P0 δ, fp = Σ P1 δ, fn = Σ P0 (1−δ).
Scores SoftScores(const Eigen::VectorXd& relevance, const std::vector<bool>& moveable);

// Thresholded-soft at θ: objects with P1 >= θ add P1 to tp, background with
// P1 >= θ add P1 to fp, objects below θ add 1 − P1 to fn, background below θ
// add 1 − P1 to tn.
Scores ThresholdedSoftScores(const Eigen::VectorXd& relevance, const std::vector<bool>& moveable,
                             double threshold = 0.5);

// Mean of the two per-class recalls when moveable means P1 >= θ: insensitive to
// the class balance of the test set (0.5 for any constant prediction). Undefined
// when a class is absent.
std::optional<double> BalancedAccuracy(const Eigen::VectorXd& relevance,
                                       const std::vector<bool>& moveable, double threshold = 0.5);

// Mean of −log P(true class) with P1 clipped to [1e-15, 1 − 1e-15], so that one
// confident mistake costs about 34.5 instead of +∞. Undefined for no sample.
std::optional<double> LogLoss(const Eigen::VectorXd& relevance, const std::vector<bool>& moveable);

// Mean of (P1 − y)² with y = 1 for moveable. Undefined for no sample.
std::optional<double> BrierScore(const Eigen::VectorXd& relevance,
                                 const std::vector<bool>& moveable);

}  // namespace relmap::metrics
