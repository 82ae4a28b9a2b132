// The temperature of the calibrated prediction (§3.3 of docs/method.md): the
// factor τ ∈ [0, 1] on the log-odds that makes the model's leave-one-out
// predictions of its own samples as likely as they can be (Platt scaling
// without an intercept, so that the classes keep equal prior weight).
#pragma once

#include <span>

namespace relmap::cmm {

// argmax over τ ∈ [0, 1] of Σ_i log σ(τ z_i), where z_i is the log-odds in
// favour of sample i's own label. The objective is concave, so its derivative
// Σ z_i σ(−τ z_i) decreases: 1 if it is still >= 0 at τ = 1 (the densities are
// not overconfident), 0 if it is <= 0 at τ = 0 (they predict no better than a
// coin), else its root, by Newton steps kept inside a shrinking bracket.
// Deterministic; O(n) per step, a few dozen steps at most.
double FitTemperature(std::span<const double> log_odds);

}  // namespace relmap::cmm
