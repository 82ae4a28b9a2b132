// The novelty term (§4.4): hand-computed values, its scale-freeness, and what it
// does to the choice map.
#include "exploration/novelty.h"

#include <gtest/gtest.h>

#include "exploration/choice.h"

namespace relmap::exploration {
namespace {

cmm::Dataset Labelled(const Eigen::MatrixXd& rows) {
  cmm::Dataset data(static_cast<int>(rows.cols()));
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    data.Append(rows.row(i).transpose(), static_cast<int>(i % 2));
  }
  return data;
}

TEST(Novelty, IsOneUntilTwoSamplesGiveAScale) {
  cmm::Dataset data(2);
  const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(5, 2);
  EXPECT_TRUE(Novelty(candidates, data).isApproxToConstant(1.0, 0.0));
  data.Append(Eigen::Vector2d(0, 0), 0);
  EXPECT_TRUE(Novelty(candidates, data).isApproxToConstant(1.0, 0.0));
}

TEST(Novelty, MatchesTheHandComputedValues) {
  // Samples (0,0) and (2,0): variance 2 in x, 0 in y; floor 0.01·mean = 0.01,
  // so x is scaled by 1/√2.01 and y by 1/√0.01 = 10.
  Eigen::MatrixXd samples(2, 2);
  samples << 0, 0, 2, 0;
  const cmm::Dataset data = Labelled(samples);
  Eigen::MatrixXd candidates(3, 2);
  candidates << 0, 0,  // on a sample: d² = 0
      1, 0,            // halfway: d² = 1/2.01
      2, 0.1;          // above the second: d² = 0.01·100 = 1
  const Eigen::VectorXd g = Novelty(candidates, data);
  const double h2 = 1.0 / 2.01;  // the median of {0, 1/2.01, 1}
  EXPECT_DOUBLE_EQ(g[0], 0.0);
  EXPECT_NEAR(g[1], 0.5, 1e-12);
  EXPECT_NEAR(g[2], 1.0 / (1.0 + h2), 1e-12);
}

TEST(Novelty, DoesNotDependOnTheFeaturesScaleOrOrigin) {
  const Eigen::MatrixXd samples = Eigen::MatrixXd::Random(20, 3);
  const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(9, 3);
  const Eigen::VectorXd g = Novelty(candidates, Labelled(samples));
  const Eigen::RowVector3d origin(5, -2, 40);
  const Eigen::VectorXd moved = Novelty((1000.0 * candidates).rowwise() + origin,
                                        Labelled((1000.0 * samples).rowwise() + origin));
  EXPECT_TRUE(g.isApprox(moved, 1e-6));
}

TEST(Novelty, TurnsTheChoiceAwayFromRowsThatRepeatASample) {
  Eigen::MatrixXd samples(2, 1);
  samples << 0, 1;
  Eigen::MatrixXd candidates(3, 1);
  candidates << 0, 0.5, 3;
  const Eigen::VectorXd g = Novelty(candidates, Labelled(samples));
  const Eigen::VectorXd same = Eigen::VectorXd::Constant(3, 0.5);
  ExplorationConfig config;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
  const Eigen::VectorXd choice = ChoiceMap({same, same, zero, g}, config);
  EXPECT_DOUBLE_EQ(choice[0], 0.0);
  EXPECT_LT(choice[1], choice[2]);
  EXPECT_NEAR(choice.sum(), 1.0, 1e-12);
}

TEST(ChoiceMap, RandomShareMixesInTheUniformMap) {
  ExplorationConfig config;
  config.random_share = 0.2;
  Eigen::VectorXd u(4);
  u << 1, 0, 0, 0;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(4);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(4);
  const Eigen::VectorXd choice = ChoiceMap({ones, u, zero, ones}, config);
  EXPECT_NEAR(choice[0], 0.8 + 0.05, 1e-12);
  EXPECT_NEAR(choice[1], 0.05, 1e-12);
  EXPECT_NEAR(choice.sum(), 1.0, 1e-12);
}

// r = (0.9, 0.1, 0.5, 0.5): Σr = 2, Σ(1 − r) = 2, so w_i = ½ r_i/2 + ½ (1 − r_i)/2 = ¼ for
// every point, whatever u and c; with r = (1, 0, 0, 0) the one likely-moveable point gets
// half the draws and the three others a sixth each.
TEST(ChoiceMap, TheClassBalancedRuleDrawsHalfAmongEachPredictedClass) {
  ExplorationConfig config;
  config.rule = ChoiceRule::kClassBalanced;
  Eigen::VectorXd u(4);
  u << 1, 0, 0, 0;
  const Eigen::VectorXd c = Eigen::VectorXd::Zero(4);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(4);
  Eigen::VectorXd r(4);
  r << 0.9, 0.1, 0.5, 0.5;
  // P = {0, 2, 3} (r ≥ ½), N = {1}: ½ spread over P, ½ on the one in N; u and c play no part.
  Eigen::VectorXd expected(4);
  expected << 1.0 / 6.0, 0.5, 1.0 / 6.0, 1.0 / 6.0;
  EXPECT_TRUE(ChoiceMap({r, u, c, ones}, config).isApprox(expected));
  // With novelty g = (½, 1, 0, 1): P's half in proportion to g, (½, 0, 1) / 1.5.
  Eigen::VectorXd g(4);
  g << 0.5, 1, 0, 1;
  expected << 1.0 / 6.0, 0.5, 0.0, 1.0 / 3.0;
  EXPECT_TRUE(ChoiceMap({r, u, c, g}, config).isApprox(expected));
  // A sure prediction does not weigh more: one supervoxel predicted moveable gets ½.
  const Eigen::VectorXd& one_moveable = u;  // (1, 0, 0, 0)
  expected << 0.5, 1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0;
  EXPECT_TRUE(ChoiceMap({one_moveable, u, c, ones}, config).isApprox(expected));
  // Everything predicted moveable (an untrained model's ½ too): the other half is empty
  // and the first takes all.
  EXPECT_TRUE(ChoiceMap({ones, u, c, ones}, config).isApprox(Eigen::VectorXd::Constant(4, 0.25)));
  const Eigen::VectorXd untrained = Eigen::VectorXd::Constant(4, 0.5);
  EXPECT_TRUE(
      ChoiceMap({untrained, u, c, ones}, config).isApprox(Eigen::VectorXd::Constant(4, 0.25)));
}

TEST(ChoiceMap, ThePapersOptionsGiveThePapersMap) {
  const Eigen::VectorXd u = Eigen::VectorXd::Random(6).cwiseAbs();
  const Eigen::VectorXd c = Eigen::VectorXd::Random(6).cwiseAbs() * 0.9;
  const Eigen::VectorXd paper = ChoiceMap(u, c, false);
  const Eigen::VectorXd w = u.array() * (1.0 - c.array());
  EXPECT_TRUE(paper.isApprox(w / w.sum(), 0.0));
  const Eigen::VectorXd r = Eigen::VectorXd::Random(6).cwiseAbs();
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(6);
  EXPECT_EQ(paper, ChoiceMap({r, u, c, ones}, ExplorationConfig{}));
}

}  // namespace
}  // namespace relmap::exploration
