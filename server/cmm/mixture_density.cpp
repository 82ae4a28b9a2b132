// Two passes per point: the largest term, then the sum of exponentials around it.
// Terms more than kNegligible below the largest are not exponentiated: e^−50 ≈
// 2e−22, so even a thousand of them change the sum (>= 1 relative to the largest
// term) by less than one rounding. In 48-d most components are that far from a
// given point, and exp() was the cost of evaluating a candidate split or merge.
#include "cmm/mixture_density.h"

#include <algorithm>
#include <cmath>

#include "cmm/log_math.h"

namespace relmap::cmm {
namespace {

constexpr double kNegligible = 50.0;

}  // namespace

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
      if (relative > -kNegligible) sum[i] += std::exp(relative);
    }
  }
  for (int i = 0; i < n; ++i) {
    if (high[i] != kNegativeInfinity) high[i] += std::log(sum[i]);
  }
  return high;
}

}  // namespace relmap::cmm
