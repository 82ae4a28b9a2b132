// One learner on one stream: online training in stream order with a learning
// curve, then the held-out scores.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "learning_bench/online_learner.h"
#include "learning_bench/streams.h"
#include "tools/cmm/latency.h"

namespace relmap::learning_bench {

struct CurvePoint {
  int samples = 0;
  std::optional<double> balanced_accuracy;  // on the test set
};

// Test-set scores after the whole training set (moveable = label 1). Each is
// undefined where its metric is (common/metrics.h).
struct RunResult {
  std::optional<double> balanced_accuracy;
  std::optional<double> soft_accuracy;  // the paper's soft metric
  std::optional<double> log_loss;
  std::optional<double> brier;
  std::optional<std::array<int, 2>> components;
  double predict_us = 0.0;  // per test sample, predicted in one batch
  std::vector<CurvePoint> curve;
};

// Trains `learner` on stream.train row by row, timing each Learn call into
// `updates`; every `curve_every` samples (and after the last) it scores the
// test set for the curve. A sample the learner rejects → that error.
StatusOr<RunResult> RunLearner(OnlineLearner& learner, const Stream& stream, int curve_every,
                               tools::LatencyRecorder& updates);

}  // namespace relmap::learning_bench
