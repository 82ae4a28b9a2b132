// The training loop and the scoring, shared by every learner so that all of
// them see the same samples in the same order.
#include "learning_bench/evaluation.h"

#include <chrono>
#include <string>

#include "common/metrics.h"

namespace relmap::learning_bench {

StatusOr<RunResult> RunLearner(OnlineLearner& learner, const Stream& stream, int curve_every,
                               tools::LatencyRecorder& updates) {
  const std::vector<bool> moveable(stream.test.labels.begin(), stream.test.labels.end());
  RunResult result;
  const auto n = static_cast<int>(stream.train.features.rows());
  for (int i = 0; i < n; ++i) {
    const Status status = updates.Time([&] {
      return learner.Learn(stream.train.features.row(i).transpose(), stream.train.labels[i]);
    });
    if (!status.ok()) {
      return InvalidArgumentError(stream.name + ": training sample " + std::to_string(i + 1) +
                                  ": " + status.message());
    }
    if ((curve_every > 0 && (i + 1) % curve_every == 0) || i + 1 == n) {
      result.curve.push_back(
          {i + 1, metrics::BalancedAccuracy(learner.Predict(stream.test.features), moveable)});
    }
  }

  const auto start = std::chrono::steady_clock::now();
  const Eigen::VectorXd p = learner.Predict(stream.test.features);
  const std::chrono::duration<double, std::micro> predict =
      std::chrono::steady_clock::now() - start;
  result.predict_us = predict.count() / static_cast<double>(std::max<Eigen::Index>(1, p.size()));

  result.balanced_accuracy = metrics::BalancedAccuracy(p, moveable);
  result.soft_accuracy = metrics::SoftScores(p, moveable).accuracy;
  result.log_loss = metrics::LogLoss(p, moveable);
  result.brier = metrics::BrierScore(p, moveable);
  result.components = learner.Components();
  return result;
}

}  // namespace relmap::learning_bench
