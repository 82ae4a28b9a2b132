// The calibration of the prediction (§3.3 of docs/method.md): a temperature
// τ ∈ [0, 1] on the log-odds and a label-noise rate ε, so that
//   P(label | x) = ε/2 + (1 − ε)·σ(τ·z(x)),
// fitted to make the model's leave-one-out predictions of its own samples as
// likely as they can be. τ tempers densities that are overconfident (48-d
// Gaussians are); ε is the share of labels no model of x explains (a change
// detector's mistakes), so that they cost each at most log(2/ε) instead of
// dragging τ towards 0. No intercept: the classes keep equal prior weight.
#pragma once

#include <span>

namespace relmap::cmm {

struct Calibration {
  double temperature = 1.0;  // τ
  double label_noise = 0.0;  // ε
};

// log P(label | x) for the log-odds z in favour of that label.
double LogCalibratedProbability(double log_odds, const Calibration& calibration);

// Towards argmax over τ ∈ [0, 1], ε ∈ [0.001, ½] of Σ_i log(ε/2 + (1 − ε)σ(τ z_i)),
// where z_i is the log-odds in favour of sample i's own label: at most eight
// iterations of EM from `start` (ε: the expected share of noise labels; τ: the
// weighted FitTemperature from the current τ).
// Deterministic for the same inputs and start.
Calibration FitCalibration(std::span<const double> log_odds, const Calibration& start);

// argmax over τ ∈ [0, 1] of Σ_i w_i log σ(τ z_i) (w = 1 if empty). The objective
// is concave, so its derivative Σ w_i z_i σ(−τ z_i) decreases: 1 if it is still
// >= 0 at τ = 1, 0 if it is <= 0 at τ = 0, else its root, by Newton steps from
// `start` kept inside a shrinking bracket.
double FitTemperature(std::span<const double> log_odds, std::span<const double> weights = {},
                      double start = 0.5);

// z σ(−τz), one sample's term of the derivative in τ of Σ_i log σ(τ z_i).
double TemperatureSlope(double log_odds, double temperature);

// LogCalibratedProbability(z, {τ, 0}) and TemperatureSlope(z, τ) from one exp:
// log σ(τz) and σ(−τz) need the same e^−|τz|, so both come out with the bits of
// the two calls.
struct ProbabilityAndSlope {
  double log_probability;
  double slope;
};
ProbabilityAndSlope LogProbabilityAndSlope(double log_odds, double temperature);

}  // namespace relmap::cmm
