// log Γ(x) = log Σ_k w_k G_k(x) of a class mixture, for many points at once, from
// per-component columns of log-densities.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace relmap::cmm {

struct WeightedColumn {
  std::span<const double> log_density;  // log G_k(x_i), one value per point
  double log_weight;                    // log w_k
};

// Terms more than this below the largest are not exponentiated: e^−50 ≈ 2e−22,
// so even a thousand of them change a sum (>= 1 relative to the largest term)
// by less than one rounding.
inline constexpr double kNegligibleLogTerm = 50.0;

// Log-sum-exp over the components for each of the `n` points; −∞ where every
// term is −∞ (no component, or only distant "hit" components).
Eigen::VectorXd MixtureLogDensity(const std::vector<WeightedColumn>& columns, int n);
// The same value for point i alone, by the same operations (the same bits);
// `largest`, if given, receives its largest term.
double MixtureLogDensityAt(const std::vector<WeightedColumn>& columns, int i,
                           double* largest = nullptr);

// log Σ_t e^{terms[t]} of one point, the same two passes; −∞ when every term is.
// `largest`, if given, receives the largest term.
double LogSumExp(std::span<const double> terms, double* largest = nullptr);

}  // namespace relmap::cmm
