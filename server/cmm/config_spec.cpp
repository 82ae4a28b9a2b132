// Parsing and naming of text CMM configurations (config_spec.h).
#include "cmm/config_spec.h"

#include <charconv>
#include <cmath>
#include <vector>

namespace relmap::cmm {
namespace {

// The shortest text that reads back as `value`.
std::string Shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string Option(std::string_view key, std::string_view value) {
  return std::string(key) + "=" + std::string(value);
}

template <typename Enum>
struct Word {
  std::string_view text;
  Enum value;
};

constexpr Word<CovarianceEstimate> kCovariance[] = {{"ridge", CovarianceEstimate::kRidge},
                                                    {"prior", CovarianceEstimate::kPooledPrior}};
constexpr Word<AcceptanceTest> kAcceptance[] = {{"training", AcceptanceTest::kTrainingLikelihood},
                                                {"loo", AcceptanceTest::kLeaveOneOut}};
constexpr Word<SplitOverlap> kOverlap[] = {{"mean", SplitOverlap::kOtherMean},
                                           {"samples", SplitOverlap::kOtherSamples}};
constexpr Word<Prediction> kPrediction[] = {{"pseudo_count", Prediction::kPseudoCount},
                                            {"calibrated", Prediction::kCalibrated}};

constexpr Word<bool> kOnOff[] = {{"on", true}, {"off", false}};

template <typename Enum, std::size_t N>
Status ParseWord(std::string_view key, std::string_view text, const Word<Enum> (&words)[N],
                 Enum& out) {
  std::string expected;
  for (const auto& w : words) {
    if (w.text == text) {
      out = w.value;
      return OkStatus();
    }
    expected += (expected.empty() ? "" : " | ") + std::string(w.text);
  }
  return InvalidArgumentError("configuration option " + Option(key, text) + " is not one of " +
                              expected);
}

template <typename Enum, std::size_t N>
std::string_view WordOf(const Word<Enum> (&words)[N], Enum value) {
  for (const auto& w : words) {
    if (w.value == value) return w.text;
  }
  return "?";
}

Status ParseDouble(std::string_view key, std::string_view text, double& out) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return InvalidArgumentError("configuration option " + Option(key, text) +
                                " is not a finite number");
  }
  out = value;
  return OkStatus();
}

Status ApplyOption(std::string_view key, std::string_view value, CmmConfig& c) {
  if (key == "alpha") return ParseDouble(key, value, c.alpha);
  if (key == "regularization") return ParseDouble(key, value, c.regularization);
  if (key == "pseudo_samples") return ParseDouble(key, value, c.prior_pseudo_samples);
  if (key == "variance_floor") return ParseDouble(key, value, c.variance_floor);
  if (key == "max_merge_candidates") {
    double n = 0.0;
    if (Status status = ParseDouble(key, value, n); !status.ok()) return status;
    if (n < 0.0 || n > 1e6 || n != std::floor(n)) {
      return InvalidArgumentError("configuration option " + Option(key, value) +
                                  " is not a count in [0, 1e6]");
    }
    c.max_merge_candidates = static_cast<int>(n);
    return OkStatus();
  }
  if (key == "covariance") return ParseWord(key, value, kCovariance, c.covariance);
  if (key == "acceptance") return ParseWord(key, value, kAcceptance, c.acceptance);
  if (key == "overlap") return ParseWord(key, value, kOverlap, c.split_overlap);
  if (key == "prediction") return ParseWord(key, value, kPrediction, c.prediction);
  if (key == "label_noise") return ParseWord(key, value, kOnOff, c.fit_label_noise);
  return InvalidArgumentError(
      "unknown configuration option '" + std::string(key) +
      "' (expected alpha, regularization, pseudo_samples, variance_floor, max_merge_candidates, "
      "covariance, acceptance, overlap, prediction or label_noise)");
}

}  // namespace

StatusOr<CmmConfig> ParseConfiguration(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  auto variant = ParseVariant(spec.substr(0, colon));
  if (!variant.ok()) return variant.status();
  CmmConfig config = CmmConfig::ForVariant(*variant);
  std::string_view options = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  while (!options.empty()) {
    const std::size_t next = options.find(':');
    const std::string_view option = options.substr(0, next);
    options = next == std::string_view::npos ? "" : options.substr(next + 1);
    const std::size_t equals = option.find('=');
    if (equals == std::string_view::npos) {
      return InvalidArgumentError("configuration option '" + std::string(option) +
                                  "' is not key=value");
    }
    if (Status status = ApplyOption(option.substr(0, equals), option.substr(equals + 1), config);
        !status.ok()) {
      return status;
    }
  }
  if (Status status = Validate(config); !status.ok()) return status;
  return config;
}

std::string ConfigurationName(const CmmConfig& config) {
  const CmmConfig preset = CmmConfig::ForVariant(config.variant);
  std::vector<std::string> changed;
  const auto number = [&](std::string_view key, double value, double preset_value) {
    if (value != preset_value) changed.push_back(Option(key, Shortest(value)));
  };
  number("alpha", config.alpha, preset.alpha);
  number("regularization", config.regularization, preset.regularization);
  number("pseudo_samples", config.prior_pseudo_samples, preset.prior_pseudo_samples);
  number("variance_floor", config.variance_floor, preset.variance_floor);
  number("max_merge_candidates", config.max_merge_candidates, preset.max_merge_candidates);
  const auto word = [&](std::string_view key, auto value, auto preset_value, const auto& words) {
    if (value != preset_value) changed.push_back(Option(key, WordOf(words, value)));
  };
  word("covariance", config.covariance, preset.covariance, kCovariance);
  word("acceptance", config.acceptance, preset.acceptance, kAcceptance);
  word("overlap", config.split_overlap, preset.split_overlap, kOverlap);
  word("prediction", config.prediction, preset.prediction, kPrediction);
  word("label_noise", config.fit_label_noise, preset.fit_label_noise, kOnOff);
  std::string name(VariantName(config.variant));
  for (const std::string& option : changed) name += ":" + option;
  return name;
}

}  // namespace relmap::cmm
