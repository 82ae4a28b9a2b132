// Scores of a relevance map against ground truth (§6): the paper's soft metric
// and the thresholded-soft metric behind the authors' published numbers.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace relmap::exploration {

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

}  // namespace relmap::exploration
