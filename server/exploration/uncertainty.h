// Uncertainty of a prediction (§4.1): highest near p = 0.5, and skewed so that
// exploration favours the rarer class.
#pragma once

namespace relmap::exploration {

// f(x) = −2x(ln(2x) − 1) for x >= 0.5, −4x²(ln(4x²) − 1) for x < 0.5 (f(0) = 0).
double UncertaintyShape(double x);

// u = f(p) if |S1| <= |S0| (moveables are the minority or tied), else f(1 − p).
// With `uncertainty_bug` (the later tag): f(p) only if |S1| < |S0|, else f(p − 1).
double Uncertainty(double relevance, int moveable_samples, int non_moveable_samples,
                   bool uncertainty_bug = false);

}  // namespace relmap::exploration
