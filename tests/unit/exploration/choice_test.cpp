// Confidence (§4.2), the choice map and the seeded draw of the target (§4.3).
#include "exploration/choice.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relmap::exploration {
namespace {

cmm::Evaluation EvaluationWith(std::initializer_list<double> squared,
                               std::initializer_list<double> log_membership) {
  cmm::Evaluation e;
  e.nearest_squared_mahalanobis =
      Eigen::Map<const Eigen::VectorXd>(squared.begin(), static_cast<Eigen::Index>(squared.size()));
  e.nearest_log_membership = Eigen::Map<const Eigen::VectorXd>(
      log_membership.begin(), static_cast<Eigen::Index>(log_membership.size()));
  e.relevance = Eigen::VectorXd::Constant(e.nearest_squared_mahalanobis.size(), 0.5);
  return e;
}

TEST(Confidence, IsOneAtAComponentMeanAndVanishesFarAway) {
  const auto e = EvaluationWith({0.0, 2.0, INFINITY}, {0.0, 0.0, -INFINITY});
  const Eigen::VectorXd c = Confidence(e, ConfidenceMode::kNearestPeak);
  EXPECT_DOUBLE_EQ(c[0], 1.0);
  EXPECT_DOUBLE_EQ(c[1], std::exp(-1.0));  // exp(−½·2)
  EXPECT_DOUBLE_EQ(c[2], 0.0);             // no component at all
}

TEST(Confidence, MembershipModeIsTheMembershipProbability) {
  const auto e = EvaluationWith({5.0, 5.0}, {0.0, std::log(0.25)});
  const Eigen::VectorXd c = Confidence(e, ConfidenceMode::kMembership);
  EXPECT_DOUBLE_EQ(c[0], 1.0);  // one component in its class: frozen at 1
  EXPECT_DOUBLE_EQ(c[1], 0.25);
}

TEST(ChoiceMap, IsUniformBeforeAnySample) {
  // Untrained: relevance 0.5 → u = 1, no component → c = 0, so every w = 1.
  const auto e = EvaluationWith({INFINITY, INFINITY, INFINITY, INFINITY},
                                {-INFINITY, -INFINITY, -INFINITY, -INFINITY});
  const Eigen::VectorXd u = UncertaintyMap(e.relevance, 0, 0, false);
  const Eigen::VectorXd choice = ChoiceMap(u, Confidence(e, ConfidenceMode::kNearestPeak), false);
  EXPECT_TRUE(choice.isApproxToConstant(0.25));
}

TEST(ChoiceMap, IsUncertaintyTimesOneMinusConfidenceNormalised) {
  // w = (1·0.5, 0.5·1, 1·0) = (0.5, 0.5, 0) → (0.5, 0.5, 0).
  const Eigen::Vector3d u(1.0, 0.5, 1.0);
  const Eigen::Vector3d c(0.5, 0.0, 1.0);
  const Eigen::VectorXd choice = ChoiceMap(u, c, false);
  EXPECT_DOUBLE_EQ(choice[0], 0.5);
  EXPECT_DOUBLE_EQ(choice[1], 0.5);
  EXPECT_DOUBLE_EQ(choice[2], 0.0);
  EXPECT_DOUBLE_EQ(choice.sum(), 1.0);
}

TEST(ChoiceMap, IsUniformWhenEveryWeightIsZero) {
  const Eigen::Vector2d u(1.0, 1.0);
  const Eigen::Vector2d c(1.0, 1.0);
  EXPECT_TRUE(ChoiceMap(u, c, false).isApproxToConstant(0.5));
}

TEST(ChoiceMap, PaperQuirksZeroValuesBelowOneThousandth) {
  // w = (1, 0.0005, 1): the middle value is zeroed before normalising.
  const Eigen::Vector3d u(1.0, 0.0005, 1.0);
  const Eigen::Vector3d c = Eigen::Vector3d::Zero();
  const Eigen::VectorXd paper = ChoiceMap(u, c, true);
  EXPECT_DOUBLE_EQ(paper[1], 0.0);
  EXPECT_DOUBLE_EQ(paper[0], 0.5);
  EXPECT_GT(ChoiceMap(u, c, false)[1], 0.0);
}

TEST(DrawTarget, FollowsTheChoiceMap) {
  // 40000 draws from (0.1, 0.6, 0.3, 0): each count within 5 standard deviations.
  const Eigen::Vector4d choice(0.1, 0.6, 0.3, 0.0);
  Random random(11);
  std::vector<int> counts(4, 0);
  for (int i = 0; i < 40000; ++i) ++counts[DrawTarget(choice, 100, false, random)];
  EXPECT_NEAR(counts[0], 4000, 5 * std::sqrt(40000 * 0.1 * 0.9));
  EXPECT_NEAR(counts[1], 24000, 5 * std::sqrt(40000 * 0.6 * 0.4));
  EXPECT_NEAR(counts[2], 12000, 5 * std::sqrt(40000 * 0.3 * 0.7));
  EXPECT_EQ(counts[3], 0);
}

TEST(DrawTarget, IsReproducibleFromTheSeed) {
  const Eigen::Vector4d choice(0.1, 0.6, 0.3, 0.0);
  Random a(5);
  Random b(5);
  for (int i = 0; i < 100; ++i)
    EXPECT_EQ(DrawTarget(choice, i, false, a), DrawTarget(choice, i, false, b));
}

TEST(DrawTarget, PaperQuirksDrawTheFirstElevenUniformlyButNeverTheLast) {
  // Choice mass all on the last index: the 2018 code still draws uniformly over
  // the others for the first 11 interactions, then follows the map.
  const Eigen::Vector3d choice(0.0, 0.0, 1.0);
  Random random(3);
  std::vector<int> counts(3, 0);
  for (int i = 0; i < 2000; ++i)
    ++counts[DrawTarget(choice, i % kPaperUniformChoices, true, random)];
  EXPECT_EQ(counts[2], 0);
  EXPECT_GT(counts[0], 800);
  EXPECT_GT(counts[1], 800);
  EXPECT_EQ(DrawTarget(choice, kPaperUniformChoices, true, random), 2);
}

}  // namespace
}  // namespace relmap::exploration
