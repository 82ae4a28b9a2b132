// The exploration options as text, for the command-line tools: "paper" (the
// paper's rule), or a comma-separated list of "balanced", "novelty" and "random=ε".
#pragma once

#include <string>
#include <string_view>

#include "common/status.h"
#include "exploration/exploration_config.h"

namespace relmap::exploration {

// Sets config's rule, diversity and random_share from `spec`; the other fields stay.
Status ApplyExplorationSpec(std::string_view spec, ExplorationConfig& config);

// The inverse: "paper", "balanced", "novelty", "random=0.1", "balanced,novelty,random=0.1"…
std::string ExplorationSpec(const ExplorationConfig& config);

// Validates random_share ∈ [0, 1].
Status ValidateExploration(const ExplorationConfig& config);

}  // namespace relmap::exploration
