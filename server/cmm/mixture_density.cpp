// Two passes per point: the largest term, then the sum of exponentials around it,
// skipping terms kNegligibleLogTerm below it. In 48-d most components are that
// far from a given point, and exp() was the cost of evaluating a candidate split
// or merge.
#include "cmm/mixture_density.h"

#include <algorithm>
#include <cmath>

#include "cmm/log_math.h"

namespace relmap::cmm {
Eigen::VectorXd MixtureLogDensity(const std::vector<WeightedColumn>& columns, int n) {
  Eigen::VectorXd high = Eigen::VectorXd::Constant(n, kNegativeInfinity);
  for (const auto& column : columns) {
    for (int i = 0; i < n; ++i)
      high[i] = std::max(high[i], column.log_weight + column.log_density[i]);
  }
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(n);
  for (const auto& column : columns) {
    for (int i = 0; i < n; ++i) {
      const double relative = column.log_weight + column.log_density[i] - high[i];
      if (relative > -kNegligibleLogTerm) sum[i] += std::exp(relative);
    }
  }
  for (int i = 0; i < n; ++i) {
    if (high[i] != kNegativeInfinity) high[i] += std::log(sum[i]);
  }
  return high;
}

double LogSumExp(std::span<const double> terms) {
  double high = kNegativeInfinity;
  for (const double t : terms) high = std::max(high, t);
  if (high == kNegativeInfinity) return high;
  double sum = 0.0;
  for (const double t : terms) {
    if (t - high > -kNegligibleLogTerm) sum += std::exp(t - high);
  }
  return high + std::log(sum);
}

}  // namespace relmap::cmm
