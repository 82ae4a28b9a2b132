// The uncertainty function of the paper, with its asymmetric shape f.
#include "exploration/uncertainty.h"

#include <cmath>

namespace relmap::exploration {

double UncertaintyShape(double x) {
  if (x >= 0.5) return -2.0 * x * (std::log(2.0 * x) - 1.0);
  const double four_x_squared = 4.0 * x * x;
  if (four_x_squared == 0.0) return 0.0;  // the limit of −y(ln y − 1) as y → 0
  return -four_x_squared * (std::log(four_x_squared) - 1.0);
}

double Uncertainty(double relevance, int moveable_samples, int non_moveable_samples,
                   bool uncertainty_bug) {
  if (uncertainty_bug) {
    return moveable_samples < non_moveable_samples ? UncertaintyShape(relevance)
                                                   : UncertaintyShape(relevance - 1.0);
  }
  return moveable_samples <= non_moveable_samples ? UncertaintyShape(relevance)
                                                  : UncertaintyShape(1.0 - relevance);
}

}  // namespace relmap::exploration
