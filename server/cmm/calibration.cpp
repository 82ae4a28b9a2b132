// Safeguarded Newton iteration for the temperature (calibration.h).
#include "cmm/calibration.h"

#include <cmath>

namespace relmap::cmm {
namespace {

constexpr int kMaxSteps = 60;
constexpr double kBracketWidth = 1e-10;

double Sigmoid(double t) {
  return t >= 0.0 ? 1.0 / (1.0 + std::exp(-t)) : std::exp(t) / (1.0 + std::exp(t));
}

// The objective's first and (negated) second derivative at τ.
struct Slope {
  double gradient = 0.0;   // Σ z σ(−τz)
  double curvature = 0.0;  // Σ z² σ(τz) σ(−τz) >= 0
};

Slope SlopeAt(std::span<const double> z, double tau) {
  Slope s;
  for (const double zi : z) {
    const double wrong = Sigmoid(-tau * zi);
    s.gradient += zi * wrong;
    s.curvature += zi * zi * wrong * (1.0 - wrong);
  }
  return s;
}

}  // namespace

double FitTemperature(std::span<const double> log_odds) {
  double low = 0.0;
  double high = 1.0;
  if (SlopeAt(log_odds, high).gradient >= 0.0) return high;
  if (SlopeAt(log_odds, low).gradient <= 0.0) return low;
  double tau = 0.5;
  for (int step = 0; step < kMaxSteps && high - low > kBracketWidth; ++step) {
    const Slope s = SlopeAt(log_odds, tau);
    if (s.gradient == 0.0) return tau;
    (s.gradient > 0.0 ? low : high) = tau;
    const double newton = s.curvature > 0.0 ? tau + s.gradient / s.curvature : -1.0;
    tau = newton > low && newton < high ? newton : 0.5 * (low + high);
  }
  return tau;
}

}  // namespace relmap::cmm
