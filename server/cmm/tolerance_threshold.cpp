// Fisher quantile of the tolerance hyperellipsoid, via Boost.Math.
#include "cmm/tolerance_threshold.h"

#include <boost/math/distributions/fisher_f.hpp>
#include <limits>

namespace relmap::cmm {

double ToleranceThreshold(int n, int p, double alpha) {
  if (n <= p || alpha >= 1.0) return 0.0;
  if (alpha <= 0.0) return std::numeric_limits<double>::infinity();
  const double nd = n;
  const double pd = p;
  const boost::math::fisher_f fisher(pd, nd - pd);
  // F⁻¹_{1−α} as the complement quantile at α: accurate also for small α.
  const double quantile = boost::math::quantile(boost::math::complement(fisher, alpha));
  return ((nd - 1.0) * pd / (nd - pd)) * ((nd + 1.0) / nd) * quantile;
}

double ToleranceThresholdTable::operator()(int n) {
  if (n <= p_) return 0.0;
  if (static_cast<int>(by_n_.size()) <= n) {
    by_n_.resize(n + 1, std::numeric_limits<double>::quiet_NaN());
  }
  double& t = by_n_[n];
  if (t != t) t = ToleranceThreshold(n, p_, alpha_);  // NaN marks "not computed yet"
  return t;
}

}  // namespace relmap::cmm
