// The §6 scores (soft, thresholded-soft, undefined ratios) and the benchmark's
// balanced accuracy, log-loss and Brier score.
#include "common/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relmap::metrics {
namespace {

TEST(Metrics, SoftScoresFollowThePaperEquations) {
  // Two objects (P1 = 0.9, 0.6) and two background (P1 = 0.2, 0.5):
  // tp = 1.5, fn = 0.5, fp = 0.7, tn = 1.3 → precision 1.5/2.2, recall 0.75,
  // accuracy ½(1.5/2 + 1.3/2) = 0.7.
  const Eigen::Vector4d p(0.9, 0.6, 0.2, 0.5);
  const std::vector<bool> moveable{true, true, false, false};
  const Scores s = SoftScores(p, moveable);
  EXPECT_NEAR(*s.precision, 1.5 / 2.2, 1e-12);
  EXPECT_NEAR(*s.recall, 0.75, 1e-12);
  EXPECT_NEAR(*s.accuracy, 0.7, 1e-12);
}

TEST(Metrics, ThresholdedSoftScoresOfAnUntrainedModel) {
  // All P1 = 0.5 >= θ: tp = 0.5·objects, fp = 0.5·background, fn = tn = 0 →
  // recall 1 and accuracy ½(0.5 + 0) = 0.25, as docs/method.md §6 says.
  const Eigen::Vector4d p = Eigen::Vector4d::Constant(0.5);
  const std::vector<bool> moveable{true, false, false, false};
  const Scores s = ThresholdedSoftScores(p, moveable);
  EXPECT_DOUBLE_EQ(*s.recall, 1.0);
  EXPECT_DOUBLE_EQ(*s.accuracy, 0.25);
  EXPECT_DOUBLE_EQ(*s.precision, 0.25);
}

TEST(Metrics, UndefinedRatiosAreNullNotNumbers) {
  const Eigen::Vector2d p(0.3, 0.4);
  const Scores s = SoftScores(p, {false, false});  // no object at all
  EXPECT_FALSE(s.recall.has_value());
  EXPECT_FALSE(s.accuracy.has_value());
  EXPECT_TRUE(s.precision.has_value());
}

TEST(Metrics, BalancedAccuracyIsTheMeanOfTheTwoRecalls) {
  // Three objects (P1 = 0.9, 0.5, 0.4) and one background (P1 = 0.2): at θ = 0.5
  // the objects give recall 2/3 (0.5 counts as moveable), the background 1/1 →
  // ½(2/3 + 1) = 5/6, where plain accuracy would be 3/4.
  const Eigen::Vector4d p(0.9, 0.5, 0.4, 0.2);
  const std::vector<bool> moveable{true, true, true, false};
  EXPECT_NEAR(*BalancedAccuracy(p, moveable), 5.0 / 6.0, 1e-12);
}

TEST(Metrics, BalancedAccuracyOfAConstantPredictionIsOneHalf) {
  // Everything predicted moveable: recall 1 for objects, 0 for background.
  const Eigen::Vector4d p = Eigen::Vector4d::Constant(0.7);
  EXPECT_DOUBLE_EQ(*BalancedAccuracy(p, {true, false, false, false}), 0.5);
}

TEST(Metrics, BalancedAccuracyIsUndefinedWithoutBothClasses) {
  EXPECT_FALSE(BalancedAccuracy(Eigen::Vector2d(0.3, 0.8), {true, true}).has_value());
}

TEST(Metrics, LogLossIsTheMeanNegativeLogProbabilityOfTheTruth) {
  // An object with P1 = 0.8 costs −log 0.8; a background with P1 = 0.4 costs
  // −log 0.6 → mean ½(0.22314355 + 0.51082562) = 0.36698459.
  const Eigen::Vector2d p(0.8, 0.4);
  EXPECT_NEAR(*LogLoss(p, {true, false}), 0.5 * (-std::log(0.8) - std::log(0.6)), 1e-12);
  EXPECT_NEAR(*LogLoss(p, {true, false}), 0.36698459, 1e-8);
}

TEST(Metrics, LogLossClipsCertainMistakes) {
  // P1 = 0 for an object: −log(1e-15) = 15 ln 10 = 34.538776, not +∞; P1 = 1
  // for an object costs −log(1 − 1e-15) ≈ 1e-15.
  const Eigen::Vector2d p(0.0, 1.0);
  EXPECT_NEAR(*LogLoss(p, {true, true}), 0.5 * 15.0 * std::log(10.0), 1e-9);
}

TEST(Metrics, BrierScoreIsTheMeanSquaredErrorOfP1) {
  // (0.8 − 1)² = 0.04, (0.4 − 0)² = 0.16, (0.5 − 1)² = 0.25 → 0.45 / 3 = 0.15.
  const Eigen::Vector3d p(0.8, 0.4, 0.5);
  EXPECT_NEAR(*BrierScore(p, {true, false, true}), 0.15, 1e-12);
}

TEST(Metrics, LogLossAndBrierAreUndefinedWithoutSamples) {
  const Eigen::VectorXd none(0);
  EXPECT_FALSE(LogLoss(none, {}).has_value());
  EXPECT_FALSE(BrierScore(none, {}).has_value());
}

}  // namespace
}  // namespace relmap::metrics
