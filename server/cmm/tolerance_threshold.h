// The tolerance hyperellipsoid of a component (§3.5): T(n, p, α) such that a point
// ρ lies inside iff (ρ − μ)ᵀ Σ⁻¹ (ρ − μ) <= T.
#pragma once

#include <vector>

namespace relmap::cmm {

// T = ((n−1)p / (n−p)) · ((n+1)/n) · F⁻¹_{1−α}(p, n−p), with F the Fisher
// distribution (Boost.Math). Returns 0 when n <= p (no covariance estimate in p
// dimensions: nothing intersects) or α = 1, and +∞ for α = 0.
double ToleranceThreshold(int n, int p, double alpha);

// Whether a squared distance lies inside a tolerance ellipsoid of threshold T. A
// threshold of 0 means "no ellipsoid": nothing intersects (α = 1, n <= p).
inline bool InsideTolerance(double squared_distance, double threshold) {
  return threshold > 0.0 && squared_distance <= threshold;
}

// T for every n at fixed p and α, computed once per n (a Fisher quantile costs
// tens of microseconds).
class ToleranceThresholdTable {
 public:
  ToleranceThresholdTable(int p, double alpha) : p_(p), alpha_(alpha) {}
  double operator()(int n);

 private:
  int p_;
  double alpha_;
  std::vector<double> by_n_;
};

}  // namespace relmap::cmm
