// Configuration of exploration (§4): how uncertainty, confidence and the choice
// map are computed, with the authors' variations as named switches.
#pragma once

#include "cmm/config.h"

namespace relmap::exploration {

enum class ConfidenceMode {
  // c(x) = exp(−½ d²_k*(x)) of the nearest component of either class: what the
  // authors' code computed (corrected_v1, paper2018). In p dimensions a sample of
  // the component itself has d² ≈ p, so in 48-d c ≈ e^−24 for every point and
  // 1 − c no longer tells covered regions from new ones.
  kNearestPeak,
  // c(x) = P(χ²_p > d²_k*(x)): the fraction of the nearest component's own
  // mass farther out than x, the same as exp(−½ d²) in 2-d and meaning the
  // same in every dimension (relmap's default, `corrected`).
  kChiSquare,
  // The paper's literal wording: the membership probability (eq. comp_est) of
  // the nearest component within its class. Frozen at 1 while a class has one
  // component; kept for study only.
  kMembership,
};

// What the choice map weighs before the diversity term and the random share (§4.4).
enum class ChoiceRule {
  kUncertainty,  // w = u (1 − c): the paper's rule
  // w = ½ 1[r ≥ ½]/|P| + ½ 1[r < ½]/|N|, r the relevance, P and N the supervoxels
  // predicted moveable and not: half the draws among each predicted class, uniformly
  // within it; a class-balanced sample of the scene rather than of its boundary.
  kClassBalanced,
};

// A diversity term of the choice map (§4.4).
enum class Diversity {
  kNone,     // w = u (1 − c): the paper's rule
  kNovelty,  // w = u (1 − c) g, g the novelty against the labelled samples
};

struct ExplorationConfig {
  ConfidenceMode confidence = ConfidenceMode::kNearestPeak;
  // The later published tag (§4.1): ties of the class counts go to the other
  // branch, and that branch evaluates f(p − 1) instead of f(1 − p).
  bool uncertainty_bug = false;
  // Defect 6 (paper2018): choice values below 1e-3 are zeroed, and the first
  // kPaperUniformChoices targets are drawn uniformly with an off-by-one range
  // that never picks the last supervoxel.
  bool paper_choice_quirks = false;
  ChoiceRule rule = ChoiceRule::kUncertainty;
  Diversity diversity = Diversity::kNone;
  // ε of the choice map given to a uniform draw: choice = (1 − ε) w/Σw + ε/N (§4.4).
  double random_share = 0.0;

  static ExplorationConfig ForVariant(cmm::Variant variant) {
    ExplorationConfig config;
    config.paper_choice_quirks = variant == cmm::Variant::kPaper2018;
    config.confidence = variant == cmm::Variant::kCorrected ? ConfidenceMode::kChiSquare
                                                            : ConfidenceMode::kNearestPeak;
    return config;
  }
};

// How many targets the 2018 code drew uniformly before using the choice map.
inline constexpr int kPaperUniformChoices = 11;
// Choice values the 2018 code zeroed.
inline constexpr double kPaperChoiceFloor = 1e-3;

}  // namespace relmap::exploration
