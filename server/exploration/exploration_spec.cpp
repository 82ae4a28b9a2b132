// Parsing and naming of the exploration options (exploration_spec.h).
#include "exploration/exploration_spec.h"

#include <charconv>
#include <cmath>

namespace relmap::exploration {
namespace {

constexpr std::string_view kRandomKey = "random=";

Status ApplyWord(std::string_view word, ExplorationConfig& config) {
  if (word == "paper") {
    config.rule = ChoiceRule::kUncertainty;
    config.diversity = Diversity::kNone;
    config.random_share = 0.0;
    return OkStatus();
  }
  if (word == "balanced") {
    config.rule = ChoiceRule::kClassBalanced;
    return OkStatus();
  }
  if (word == "novelty") {
    config.diversity = Diversity::kNovelty;
    return OkStatus();
  }
  if (word.starts_with(kRandomKey)) {
    const std::string_view text = word.substr(kRandomKey.size());
    double share = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), share);
    if (error == std::errc() && end == text.data() + text.size()) {
      config.random_share = share;
      return ValidateExploration(config);
    }
  }
  return InvalidArgumentError("exploration option '" + std::string(word) +
                              "' is not one of paper | balanced | novelty | random=ε");
}

}  // namespace

Status ApplyExplorationSpec(std::string_view spec, ExplorationConfig& config) {
  while (!spec.empty()) {
    const std::size_t comma = spec.find(',');
    if (Status status = ApplyWord(spec.substr(0, comma), config); !status.ok()) return status;
    spec = comma == std::string_view::npos ? std::string_view() : spec.substr(comma + 1);
  }
  return OkStatus();
}

std::string ExplorationSpec(const ExplorationConfig& config) {
  std::string spec = config.rule == ChoiceRule::kClassBalanced ? "balanced" : "";
  if (config.diversity == Diversity::kNovelty) spec += spec.empty() ? "novelty" : ",novelty";
  if (config.random_share > 0.0) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, config.random_share);
    if (!spec.empty()) spec += ',';
    spec.append(kRandomKey).append(buffer, result.ptr);
  }
  return spec.empty() ? "paper" : spec;
}

Status ValidateExploration(const ExplorationConfig& config) {
  if (!(config.random_share >= 0.0 && config.random_share <= 1.0)) {
    return InvalidArgumentError("exploration random share " + std::to_string(config.random_share) +
                                " is not in [0, 1]");
  }
  return OkStatus();
}

}  // namespace relmap::exploration
