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

// Log-sum-exp over the components for each of the `n` points; −∞ where every
// term is −∞ (no component, or only distant "hit" components).
Eigen::VectorXd MixtureLogDensity(const std::vector<WeightedColumn>& columns, int n);

}  // namespace relmap::cmm
