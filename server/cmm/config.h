// Configuration of the Collaborative Mixture Models: the paper's constants as
// defaults, and every behaviour of the authors' 2018 code as a named switch
// (docs/method.md §3.9), so that a run can turn the fixes on one at a time.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::cmm {

enum class Variant {
  // The paper's method with the defects of the 2018 code fixed and the four
  // generalisation fixes of docs/method.md §3.10 (prior, leave-one-out test,
  // sample overlap, calibration): what users get.
  kCorrected,
  kPaper2018,  // the 2018 code as it ran in the authors' robot experiments
  // The first corrected variant (2018 defects fixed, fixed λ, the paper's
  // training-likelihood test): kept for comparison and for sessions created with it.
  kCorrectedV1,
};

// How a component's covariance is estimated (§3.2).
enum class CovarianceEstimate {
  // Σ + λI with the fixed λ `regularization` (corrected_v1). In 48-d a small λ
  // leaves components of m <= p samples nearly singular and overfitted.
  kRidge,
  // The MAP estimate under an inverse-Wishart prior of κ pseudo-samples whose
  // scale Ψ is the session's pooled within-class covariance, shrunk towards
  // (tr Ψ/p)·I (OAS), plus a variance floor relative to the feature scale:
  // Σ = (S + κΨ)/(m + κ) + φI. Well-posed for any m and along constant
  // dimensions, and invariant to the units of the features.
  kPooledPrior,
};

// The test that keeps or rejects a candidate split or merge (§3.8).
enum class AcceptanceTest {
  // The labelled training log-likelihood rises strictly (the paper). It almost
  // always rises with more components, so it overfits.
  kTrainingLikelihood,
  // The leave-one-out log-likelihood of the calibrated prediction rises
  // strictly: each sample is predicted by the model with that sample taken out
  // of its component (a rank-one downdate), which estimates held-out quality.
  kLeaveOneOut,
};

// When SPLIT deems a component to overlap the other class (§3.5).
enum class SplitOverlap {
  // An other-class component's mean lies inside C's tolerance ellipsoid (the
  // paper). Never fires for interleaved classes such as two moons.
  kOtherMean,
  // An other-class sample lies inside C's tolerance ellipsoid.
  kOtherSamples,
};

// How P(L=1|x) is formed from the class mixtures Γ0 and Γ1 (§3.3).
enum class Prediction {
  // (1 + Γ1)/(2 + Γ0 + Γ1): the "+1" is a density, so the prediction depends
  // on the units of the features.
  kPseudoCount,
  // σ(τ·log((B + Γ1)/(B + Γ0))): the pseudo-count is B(x), a broad Gaussian
  // over the whole dataset, so that P → 1/2 far from the data in any units,
  // and τ ∈ [0, 1] tempers the log-odds to their leave-one-out calibration.
  kCalibrated,
};

// Each flag, when true, reproduces one behaviour of the authors' code. The
// `corrected` variant has all of them false.
struct Paper2018Switches {
  // §3.2 / defect 1: exp(-d²/2) over the pseudo-determinant of 2πΣ (no square
  // root), pseudo-inverse distances, and "hit" densities for small components.
  bool pseudo_density = false;
  // Defect 2: a component with m <= 4 samples is centred on its first sample.
  bool first_sample_mean = false;
  // Defect 3: weights are refreshed after a split, merge or new component, but
  // not after a sample is appended to an existing component.
  bool stale_weights = false;
  // Defect 4: SPLIT tests only the nearest other-class component, MERGE only the
  // nearest same-class component and only when both hold >= 5 samples.
  bool nearest_candidate_only = false;
  // Defect 5: the random re-check (§3.4 step 4) visits only classes with >= 2
  // components, stops at the first class with fewer, and excludes the index of
  // the component updated in step 2 in both classes.
  bool truncated_recheck = false;
  // Later published tag: splits and merges are accepted without the
  // log-likelihood check. Off in both variants.
  bool skip_likelihood_check = false;
};

// The values of κ tried when prior_pseudo_samples = 0: powers of two from
// half a sample (the data rule) to 256 (the prior rules up to m ≈ 256).
inline constexpr double kPseudoSampleGrid[] = {0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256};

struct CmmConfig {
  Variant variant = Variant::kCorrected;
  // Significance level of the tolerance hyperellipsoid (§3.5): 0.25 in the paper.
  double alpha = 0.25;
  // λ of Σ̃ = Σ + λI (§3.2, kRidge only).
  double regularization = 1e-6;
  CovarianceEstimate covariance = CovarianceEstimate::kPooledPrior;
  // κ of kPooledPrior; 0 means chosen from the data: at every prior checkpoint
  // the κ of kPseudoSampleGrid that maximises the leave-one-out criterion of
  // the model as it stands (how far a component should be pulled towards the
  // pooled shape depends on how local the classes' structure is: XOR blobs in
  // 48-d want κ ≈ 2, broad noisy classes far more).
  double prior_pseudo_samples = 0.0;
  // φ/(tr Ψ/p) of kPooledPrior: the variance every direction keeps, as a
  // fraction of the mean variance of the features (1e-2: a standard deviation of
  // a tenth of the typical one), so that a dimension constant in the training
  // data does not make later samples infinitely unlikely.
  double variance_floor = 1e-2;
  AcceptanceTest acceptance = AcceptanceTest::kLeaveOneOut;
  // MERGE evaluates at most this many intersecting candidates (nearest first)
  // per call; 0 = all of them (corrected_v1, paper2018). Each costs O(n·p²),
  // and with K components per class an update could evaluate ~3K of them. 4:
  // the same accuracy on the learning benchmark as all of them, and half the
  // p99 of an update on 48-d rings at n = 1000 (32 components).
  int max_merge_candidates = 4;
  SplitOverlap split_overlap = SplitOverlap::kOtherSamples;
  Prediction prediction = Prediction::kCalibrated;
  // kCalibrated: also fit the label-noise rate ε (off: τ only, ε = 0). Off:
  // measured on the learning benchmark it gains nothing on flipped labels and
  // can explain a minority class away as noise (xor48-imbalanced 0.81 vs 0.95).
  bool fit_label_noise = false;
  // Seed of the RNG that picks components for the random re-check (§3.4 step 4).
  std::uint64_t seed = 0;
  Paper2018Switches switches;

  // The preset of a variant: the generalisation fixes for kCorrected; for
  // kCorrectedV1 and kPaper2018 the paper's ridge, training-likelihood test,
  // mean overlap and pseudo-count; kPaper2018 also turns on the switches of
  // defects 1-5 (the clock reseeding of defect 7 is not reproduced, so runs
  // stay reproducible from their seed).
  static CmmConfig ForVariant(Variant variant);

  // κ before it is chosen from the data: the configured value, or the value of
  // kPseudoSampleGrid nearest (in log) to p + 2, the fewest pseudo-samples for
  // which an inverse-Wishart prior has a mean.
  double PseudoSamples(int dimension) const;
};

// Checks ranges: alpha in [0, 1], regularization > 0 and finite, κ >= 0 and
// finite, variance_floor in (0, 1], the leave-one-out test only with the prior
// (it downdates the prior's estimate), enums in range.
Status Validate(const CmmConfig& config);

std::string_view VariantName(Variant variant);
StatusOr<Variant> ParseVariant(std::string_view name);

}  // namespace relmap::cmm
