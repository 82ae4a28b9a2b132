// The §6 scores: soft, thresholded-soft, and undefined ratios.
#include "exploration/metrics.h"

#include <gtest/gtest.h>

namespace relmap::exploration {
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
  // recall 1 and accuracy ½(0.5 + 0) = 0.25, as ALGORITHMS §6 says.
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

}  // namespace
}  // namespace relmap::exploration
