// CMM configurations written as text, for the command-line tools and the
// learning benchmark: a variant's preset with some options changed, so that a
// comparison can turn the fixes of docs/method.md §3.10 off one at a time.
#pragma once

#include <string>
#include <string_view>

#include "cmm/config.h"
#include "common/status.h"

namespace relmap::cmm {

// "variant[:key=value[:key=value...]]", e.g. "corrected",
// "corrected:acceptance=training:prediction=pseudo_count",
// "corrected_v1:regularization=1e-3", "corrected:alpha=1" (colons, so that a
// comma-separated list of configurations stays one word). Keys and values:
//   alpha, regularization, pseudo_samples, variance_floor: numbers;
//   covariance = ridge | prior;  acceptance = training | loo;
//   overlap = mean | samples;     prediction = pseudo_count | calibrated;
//   label_noise = on | off.
// An unknown key or value, or a result that fails Validate → INVALID_ARGUMENT.
StatusOr<CmmConfig> ParseConfiguration(std::string_view spec);

// The options of `config` that differ from its variant's preset, in the
// syntax ParseConfiguration reads ("corrected:acceptance=training").
std::string ConfigurationName(const CmmConfig& config);

}  // namespace relmap::cmm
