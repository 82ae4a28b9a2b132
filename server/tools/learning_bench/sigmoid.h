// The logistic function, for the learners that predict from a log-odds.
#pragma once

#include <cmath>

namespace relmap::learning_bench {

// 1 / (1 + e^−z), written for each sign so that exp never overflows.
inline double Sigmoid(double z) {
  if (z >= 0) return 1.0 / (1.0 + std::exp(-z));
  const double e = std::exp(z);
  return e / (1.0 + e);
}

}  // namespace relmap::learning_bench
