// Log-domain arithmetic. Densities of 48-d Gaussians under- and overflow doubles
// (their log-normaliser alone can exceed ±200), so the classifier adds them as
// logarithms: log(e^a + e^b) computed around the largest term.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace relmap::cmm {

inline constexpr double kNegativeInfinity = -std::numeric_limits<double>::infinity();

// log 2π, in every Gaussian's log-normaliser −½·p·log 2π − ½·log det Σ.
inline const double kLogTwoPi = std::log(2.0 * std::numbers::pi);

// log(e^a + e^b); −∞ if both are −∞.
inline double LogAddExp(double a, double b) {
  const double high = std::max(a, b);
  if (high == kNegativeInfinity) return kNegativeInfinity;
  const double low = std::min(a, b);
  return high + std::log1p(std::exp(low - high));
}

// log σ(t) = −log(1 + e^−t), without overflow for either sign of t.
inline double LogSigmoid(double t) {
  return t < 0.0 ? t - std::log1p(std::exp(t)) : -std::log1p(std::exp(-t));
}

// The log-odds of class l against 1 − l: log(e^b + Γ_l) − log(e^b + Γ_{1−l}), with
// log b the pseudo-count (0 for the paper's "+1", log B(x) for the calibrated
// prediction).
inline double LogOdds(double log_gamma_own, double log_gamma_other, double log_pseudo_count) {
  return LogAddExp(log_pseudo_count, log_gamma_own) - LogAddExp(log_pseudo_count, log_gamma_other);
}

// Eq. (class_est) in the log domain: log P(L = l | x) from log Γ_l and log Γ_{1−l}.
// P = (1 + Γ_l)/(2 + Γ_0 + Γ_1) = 1/(1 + e^r) with r = log(1 + Γ_{1−l}) − log(1 + Γ_l),
// so log P = −softplus(r). Unlike log(1 + Γ_l) − log(2 + Γ_0 + Γ_1), a difference of
// two numbers near log Γ_l (≈ 200 in 48-d), this keeps the tiny log of a
// probability within 1e−100 of 1, which the likelihood comparisons of SPLIT and
// MERGE need once the training samples are classified with certainty.
inline double LogClassProbability(double log_gamma_own, double log_gamma_other) {
  const double r = LogAddExp(0.0, log_gamma_other) - LogAddExp(0.0, log_gamma_own);
  return r > 0.0 ? -(r + std::log1p(std::exp(-r))) : -std::log1p(std::exp(r));
}

}  // namespace relmap::cmm
