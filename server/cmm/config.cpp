// Variant presets and validation of the CMM configuration.
#include "cmm/config.h"

#include <cmath>
#include <string>

namespace relmap::cmm {

CmmConfig CmmConfig::ForVariant(Variant variant) {
  CmmConfig config;
  config.variant = variant;
  if (variant == Variant::kPaper2018) {
    config.switches.pseudo_density = true;
    config.switches.first_sample_mean = true;
    config.switches.stale_weights = true;
    config.switches.nearest_candidate_only = true;
    config.switches.truncated_recheck = true;
  }
  return config;
}

Status Validate(const CmmConfig& config) {
  if (!(config.alpha >= 0.0 && config.alpha <= 1.0)) {
    return InvalidArgumentError("alpha must lie in [0, 1], got " + std::to_string(config.alpha));
  }
  if (!(config.regularization > 0.0) || !std::isfinite(config.regularization)) {
    return InvalidArgumentError("regularization must be positive and finite, got " +
                                std::to_string(config.regularization));
  }
  return OkStatus();
}

std::string_view VariantName(Variant variant) {
  return variant == Variant::kPaper2018 ? "paper2018" : "corrected";
}

StatusOr<Variant> ParseVariant(std::string_view name) {
  if (name == "corrected") return Variant::kCorrected;
  if (name == "paper2018") return Variant::kPaper2018;
  return InvalidArgumentError("unknown classifier variant '" + std::string(name) +
                              "' (expected corrected or paper2018)");
}

}  // namespace relmap::cmm
