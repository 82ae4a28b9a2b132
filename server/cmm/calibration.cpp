// EM for the calibration and safeguarded Newton for the temperature
// (calibration.h).
#include "cmm/calibration.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "cmm/log_math.h"

namespace relmap::cmm {
namespace {

constexpr int kMaxNewtonSteps = 60;
constexpr double kBracketWidth = 1e-10;
// Each fit starts from the model's previous calibration, which moves little
// from one sample to the next: a few iterations suffice, and the fit goes on
// converging over the following updates.
constexpr int kMaxEmIterations = 8;
constexpr double kEmTolerance = 1e-7;
// ε above ½ would mean labels are more often wrong than right; ε stays above
// 0.1 % so that EM can still move it (at 0 it is a fixed point).
constexpr double kMaxLabelNoise = 0.25;
constexpr double kMinLabelNoise = 1e-3;

double Sigmoid(double t) {
  if (t >= 0.0) return 1.0 / (1.0 + std::exp(-t));
  // One exp, not two: with errno-setting exp the compiler may not merge the calls,
  // and this is the inner loop of every calibration fit.
  const double e = std::exp(t);
  return e / (1.0 + e);
}

// The weighted objective's first and (negated) second derivative at τ.
struct Slope {
  double gradient = 0.0;   // Σ w z σ(−τz)
  double curvature = 0.0;  // Σ w z² σ(τz) σ(−τz) >= 0
};

Slope SlopeAt(std::span<const double> z, std::span<const double> w, double tau) {
  Slope s;
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double weight = w.empty() ? 1.0 : w[i];
    // σ(0) = ½ exactly: the bracket's end τ = 0 costs no exp.
    const double wrong = tau == 0.0 ? 0.5 : Sigmoid(-tau * z[i]);
    s.gradient += weight * z[i] * wrong;
    s.curvature += weight * z[i] * z[i] * wrong * (1.0 - wrong);
  }
  return s;
}

}  // namespace

double LogCalibratedProbability(double log_odds, const Calibration& c) {
  const double model = LogSigmoid(c.temperature * log_odds);
  if (c.label_noise <= 0.0) return model;
  return LogAddExp(std::log1p(-c.label_noise) + model, std::log(0.5 * c.label_noise));
}

double TemperatureSlope(double log_odds, double temperature) {
  return log_odds * Sigmoid(-temperature * log_odds);
}

ProbabilityAndSlope LogProbabilityAndSlope(double log_odds, double temperature) {
  // As LogSigmoid(t) and Sigmoid(s) with t = τz and s = −τz = −t: for t < 0
  // both take e^t, for t >= 0 both e^−t (at t = 0 both 1).
  const double t = temperature * log_odds;
  const double s = -temperature * log_odds;
  const double e = std::exp(t < 0.0 ? t : -t);
  const double log_probability = t < 0.0 ? t - std::log1p(e) : -std::log1p(e);
  const double wrong = s >= 0.0 ? 1.0 / (1.0 + e) : e / (1.0 + e);
  return {log_probability, log_odds * wrong};
}

double FitTemperature(std::span<const double> z, std::span<const double> w, double start) {
  double low = 0.0;
  double high = 1.0;
  if (SlopeAt(z, w, high).gradient >= 0.0) return high;
  if (SlopeAt(z, w, low).gradient <= 0.0) return low;
  double tau = start > low && start < high ? start : 0.5;
  for (int step = 0; step < kMaxNewtonSteps && high - low > kBracketWidth; ++step) {
    const Slope s = SlopeAt(z, w, tau);
    if (s.gradient == 0.0) return tau;
    (s.gradient > 0.0 ? low : high) = tau;
    const double newton = s.curvature > 0.0 ? tau + s.gradient / s.curvature : -1.0;
    const double next = newton > low && newton < high ? newton : 0.5 * (low + high);
    // Newton converges from one side, so the bracket need not shrink: stop on
    // the step as well.
    if (std::abs(next - tau) < kBracketWidth) return next;
    tau = next;
  }
  return tau;
}

Calibration FitCalibration(std::span<const double> z, const Calibration& start) {
  Calibration c = start;
  if (z.empty()) return c;
  c.label_noise = std::clamp(c.label_noise, kMinLabelNoise, kMaxLabelNoise);
  std::vector<double> model_share(z.size());
  for (int iteration = 0; iteration < kMaxEmIterations; ++iteration) {
    // E: the posterior share of the model (not the noise) in each label.
    double noise = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double model = (1.0 - c.label_noise) * Sigmoid(c.temperature * z[i]);
      model_share[i] = model / (model + 0.5 * c.label_noise);
      noise += 1.0 - model_share[i];
    }
    // M: ε in closed form; τ maximising the weighted objective (bracketed
    // Newton from the current τ: a bare Newton step overshoots where the
    // objective is flat, as it is with confident log-odds).
    const Calibration previous = c;
    c.label_noise =
        std::clamp(noise / static_cast<double>(z.size()), kMinLabelNoise, kMaxLabelNoise);
    c.temperature = FitTemperature(z, model_share, c.temperature);
    if (std::abs(c.label_noise - previous.label_noise) < kEmTolerance &&
        std::abs(c.temperature - previous.temperature) < kEmTolerance) {
      break;
    }
  }
  return c;
}

}  // namespace relmap::cmm
