// Two passes per point: the largest term, then the sum of exponentials around it,
// skipping terms kNegligibleLogTerm below it. In 48-d most components are that
// far from a given point, and exp() was the cost of evaluating a candidate split
// or merge. The largest term itself is e^0 = 1 and a lone term's sum is log 1 = 0,
// exactly as exp and log return them: neither is called for them.
#include "cmm/mixture_density.h"

#include <algorithm>
#include <cmath>

#include "cmm/log_math.h"

namespace relmap::cmm {
namespace {

// e^t and log s with the values every term's maximum gives, e^0 = 1 and log 1 = 0,
// returned without the call: in 48-d most points have a single non-negligible term.
double Exp(double t) { return t == 0.0 ? 1.0 : std::exp(t); }
double Log(double s) { return s == 1.0 ? 0.0 : std::log(s); }

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
      if (relative > -kNegligibleLogTerm) sum[i] += Exp(relative);
    }
  }
  for (int i = 0; i < n; ++i) {
    if (high[i] != kNegativeInfinity) high[i] += Log(sum[i]);
  }
  return high;
}

double MixtureLogDensityAt(const std::vector<WeightedColumn>& columns, int i, double* largest) {
  double high = kNegativeInfinity;
  for (const auto& column : columns)
    high = std::max(high, column.log_weight + column.log_density[i]);
  if (largest != nullptr) *largest = high;
  double sum = 0.0;
  for (const auto& column : columns) {
    const double relative = column.log_weight + column.log_density[i] - high;
    if (relative > -kNegligibleLogTerm) sum += Exp(relative);
  }
  return high == kNegativeInfinity ? high : high + Log(sum);
}

double LogSumExp(std::span<const double> terms, double* largest) {
  double high = kNegativeInfinity;
  for (const double t : terms) high = std::max(high, t);
  if (largest != nullptr) *largest = high;
  if (high == kNegativeInfinity) return high;
  double sum = 0.0;
  for (const double t : terms) {
    if (t - high > -kNegligibleLogTerm) sum += Exp(t - high);
  }
  return high + Log(sum);
}

}  // namespace relmap::cmm
