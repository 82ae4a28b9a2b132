// The maps of a frame: untrained maps, normalisation, unusable rows, and the
// seeded target.
#include "exploration/frame_maps.h"

#include <gtest/gtest.h>

#include <limits>

namespace relmap::exploration {
namespace {

cmm::CollaborativeMixtureModels Model2d() {
  return cmm::CollaborativeMixtureModels::Create(cmm::CmmConfig{}, 2).value();
}

Eigen::MatrixXd Grid(int n) {
  Eigen::MatrixXd features(n, 2);
  for (int i = 0; i < n; ++i) features.row(i) << 0.1 * i, 0.05 * i;
  return features;
}

TEST(FrameMaps, BeforeAnySampleRelevanceIsOneHalfAndChoiceUniform) {
  const auto model = Model2d();
  Random random(1);
  const FrameMaps maps = ComputeFrameMaps(model, Grid(8), ExplorationConfig{}, 0, &random);
  EXPECT_TRUE(maps.relevance.isApproxToConstant(0.5, 0.0));
  EXPECT_TRUE(maps.choice.isApproxToConstant(1.0 / 8.0));
  EXPECT_GE(maps.target, 0);
  EXPECT_LT(maps.target, 8);
}

TEST(FrameMaps, ChoiceSumsToOneAndFavoursUncoveredRows) {
  auto model = Model2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 0).ok());
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0.1, 0.05), 1).ok());
  Random random(2);
  const FrameMaps maps = ComputeFrameMaps(model, Grid(30), ExplorationConfig{}, 2, &random);
  EXPECT_NEAR(maps.choice.sum(), 1.0, 1e-12);
  // Row 0 sits on a sample (c = 1): it is never worth pushing again.
  EXPECT_DOUBLE_EQ(maps.confidence[0], 1.0);
  EXPECT_DOUBLE_EQ(maps.choice[0], 0.0);
  EXPECT_GT(maps.choice[29], 0.0);
}

TEST(FrameMaps, RowsWithNonFiniteFeaturesGetOneHalfAndNoChoice) {
  auto model = Model2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  Eigen::MatrixXd features = Grid(6);
  features(1, 0) = std::numeric_limits<double>::quiet_NaN();
  features(4, 1) = std::numeric_limits<double>::infinity();
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    Random random(seed);
    const FrameMaps maps = ComputeFrameMaps(model, features, ExplorationConfig{}, 1, &random);
    EXPECT_EQ(maps.unusable_rows, 2);
    EXPECT_DOUBLE_EQ(maps.relevance[1], 0.5);
    EXPECT_DOUBLE_EQ(maps.choice[1], 0.0);
    EXPECT_DOUBLE_EQ(maps.choice[4], 0.0);
    EXPECT_NEAR(maps.choice.sum(), 1.0, 1e-12);
    EXPECT_NE(maps.target, 1);
    EXPECT_NE(maps.target, 4);
  }
}

TEST(FrameMaps, NoUsableRowMeansNoTarget) {
  const auto model = Model2d();
  Random random(3);
  const Eigen::MatrixXd features =
      Eigen::MatrixXd::Constant(3, 2, std::numeric_limits<double>::quiet_NaN());
  const FrameMaps maps = ComputeFrameMaps(model, features, ExplorationConfig{}, 0, &random);
  EXPECT_EQ(maps.target, -1);
  EXPECT_EQ(maps.unusable_rows, 3);
  EXPECT_DOUBLE_EQ(maps.choice.sum(), 0.0);
}

TEST(FrameMaps, WithoutAnRngNoTargetIsDrawn) {
  const auto model = Model2d();
  const FrameMaps maps = ComputeFrameMaps(model, Grid(5), ExplorationConfig{}, 0, nullptr);
  EXPECT_EQ(maps.target, -1);
  EXPECT_NEAR(maps.choice.sum(), 1.0, 1e-12);
}

TEST(FrameMaps, SameSeedSameTargets) {
  auto model = Model2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0.5, 0.2), 1).ok());
  Random a(7);
  Random b(7);
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(ComputeFrameMaps(model, Grid(40), ExplorationConfig{}, i, &a).target,
              ComputeFrameMaps(model, Grid(40), ExplorationConfig{}, i, &b).target);
  }
}

}  // namespace
}  // namespace relmap::exploration
