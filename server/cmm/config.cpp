// Variant presets and validation of the CMM configuration.
#include "cmm/config.h"

#include <cmath>
#include <string>

namespace relmap::cmm {

CmmConfig CmmConfig::ForVariant(Variant variant) {
  CmmConfig config;
  config.variant = variant;
  if (variant != Variant::kCorrected) {
    config.covariance = CovarianceEstimate::kRidge;
    config.acceptance = AcceptanceTest::kTrainingLikelihood;
    config.split_overlap = SplitOverlap::kOtherMean;
    config.prediction = Prediction::kPseudoCount;
    config.max_merge_candidates = 0;
  }
  if (variant == Variant::kPaper2018) {
    config.switches.pseudo_density = true;
    config.switches.first_sample_mean = true;
    config.switches.stale_weights = true;
    config.switches.nearest_candidate_only = true;
    config.switches.truncated_recheck = true;
  }
  return config;
}

double CmmConfig::PseudoSamples(int dimension) const {
  if (prior_pseudo_samples > 0.0) return prior_pseudo_samples;
  const double target = std::log(dimension + 2.0);
  double nearest = kPseudoSampleGrid[0];
  for (const double kappa : kPseudoSampleGrid) {
    if (std::abs(std::log(kappa) - target) < std::abs(std::log(nearest) - target)) nearest = kappa;
  }
  return nearest;
}

Status Validate(const CmmConfig& config) {
  if (!(config.alpha >= 0.0 && config.alpha <= 1.0)) {
    return InvalidArgumentError("alpha must lie in [0, 1], got " + std::to_string(config.alpha));
  }
  if (!(config.regularization > 0.0) || !std::isfinite(config.regularization)) {
    return InvalidArgumentError("regularization must be positive and finite, got " +
                                std::to_string(config.regularization));
  }
  if (!(config.prior_pseudo_samples >= 0.0) || !std::isfinite(config.prior_pseudo_samples)) {
    return InvalidArgumentError("prior_pseudo_samples must be >= 0 and finite, got " +
                                std::to_string(config.prior_pseudo_samples));
  }
  if (config.max_merge_candidates < 0) {
    return InvalidArgumentError("max_merge_candidates must be >= 0, got " +
                                std::to_string(config.max_merge_candidates));
  }
  if (!(config.variance_floor > 0.0 && config.variance_floor <= 1.0)) {
    return InvalidArgumentError("variance_floor must lie in (0, 1], got " +
                                std::to_string(config.variance_floor));
  }
  if (static_cast<unsigned>(config.covariance) > 1 ||
      static_cast<unsigned>(config.acceptance) > 1 ||
      static_cast<unsigned>(config.split_overlap) > 1 ||
      static_cast<unsigned>(config.prediction) > 1 || static_cast<unsigned>(config.variant) > 2) {
    return InvalidArgumentError("a CMM option is out of range");
  }
  if (config.acceptance == AcceptanceTest::kLeaveOneOut &&
      config.covariance != CovarianceEstimate::kPooledPrior) {
    return InvalidArgumentError("the leave-one-out test needs the pooled covariance prior");
  }
  if (config.covariance == CovarianceEstimate::kPooledPrior && config.switches.pseudo_density) {
    return InvalidArgumentError(
        "the pooled covariance prior excludes the paper2018 pseudo density");
  }
  return OkStatus();
}

std::string_view VariantName(Variant variant) {
  switch (variant) {
    case Variant::kPaper2018:
      return "paper2018";
    case Variant::kCorrectedV1:
      return "corrected_v1";
    case Variant::kCorrected:
      break;
  }
  return "corrected";
}

StatusOr<Variant> ParseVariant(std::string_view name) {
  if (name == "corrected") return Variant::kCorrected;
  if (name == "paper2018") return Variant::kPaper2018;
  if (name == "corrected_v1") return Variant::kCorrectedV1;
  return InvalidArgumentError("unknown classifier variant '" + std::string(name) +
                              "' (expected corrected, corrected_v1 or paper2018)");
}

}  // namespace relmap::cmm
