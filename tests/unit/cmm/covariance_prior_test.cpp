// The pooled covariance prior (docs/method.md §3.2): OAS shrinkage, the local
// scale from nearest-neighbour differences, the checkpoints, the MAP
// covariance of a component and its leave-one-out downdate.
#include "cmm/covariance_prior.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "cmm/component.h"
#include "common/random.h"

namespace relmap::cmm {
namespace {

TEST(OracleApproximatingShrinkage, MatchesTheHandComputedIntensity) {
  // s = diag(2, 0), n = 10, p = 2: tr s = 2, tr s² = 4,
  // ρ = ((1 − 2/2)·4 + 2²) / ((10 + 1 − 2/2)(4 − 2²/2)) = 4/20 = 0.2,
  // shrunk = 0.8·diag(2, 0) + 0.2·(2/2)·I = diag(1.8, 0.2).
  Eigen::Matrix2d s;
  s << 2, 0, 0, 0;
  const Eigen::MatrixXd shrunk = OracleApproximatingShrinkage(s, 10);
  EXPECT_NEAR(shrunk(0, 0), 1.8, 1e-15);
  EXPECT_NEAR(shrunk(1, 1), 0.2, 1e-15);
  EXPECT_EQ(shrunk(0, 1), 0.0);
}

TEST(OracleApproximatingShrinkage, LeavesAScaledIdentityAsItIs) {
  // tr s² − tr²s/p = 0: nothing to shrink towards, ρ = 1 gives s itself.
  const Eigen::MatrixXd s = 3.0 * Eigen::MatrixXd::Identity(4, 4);
  EXPECT_TRUE(OracleApproximatingShrinkage(s, 5).isApprox(s));
}

TEST(PriorCheckpoints, AreThePowersOfTwo) {
  EXPECT_TRUE(IsPriorCheckpoint(1));
  EXPECT_TRUE(IsPriorCheckpoint(2));
  EXPECT_TRUE(IsPriorCheckpoint(1024));
  EXPECT_FALSE(IsPriorCheckpoint(0));
  EXPECT_FALSE(IsPriorCheckpoint(3));
  EXPECT_FALSE(IsPriorCheckpoint(1000));
  EXPECT_EQ(PriorSampleCount(0), 0);
  EXPECT_EQ(PriorSampleCount(1), 1);
  EXPECT_EQ(PriorSampleCount(3), 2);
  EXPECT_EQ(PriorSampleCount(1000), 512);
  EXPECT_EQ(PriorSampleCount(1024), 1024);
  EXPECT_EQ(PriorSampleCount(std::numeric_limits<int>::max()), 1 << 30);
}

Dataset TwoPairs() {
  // Class 0 at (0, 0) and (2, 0), class 1 at (10, 10) and (10, 12): each
  // sample's same-class neighbour is its pair, 2 away along one axis.
  Dataset data(2);
  data.Append(Eigen::Vector2d(0, 0), 0);
  data.Append(Eigen::Vector2d(2, 0), 0);
  data.Append(Eigen::Vector2d(10, 10), 1);
  data.Append(Eigen::Vector2d(10, 12), 1);
  return data;
}

TEST(CovariancePrior, ScaleIsHalfTheNeighbourDifferenceCovariance) {
  // Differences (±2, 0) twice and (0, ±2) twice: Σ ddᵀ = diag(8, 8) over 4
  // pairs, Σ_local = diag(8, 8)/(2·4) = I; OAS leaves I alone. The between-class
  // distance (10) does not enter. φ = 1e-2 · tr(I)/2 = 0.01.
  const CovariancePrior prior = ComputeCovariancePrior(TwoPairs(), 4, CmmConfig{});
  EXPECT_TRUE(prior.scale.isApprox(Eigen::Matrix2d::Identity(), 1e-15));
  EXPECT_NEAR(prior.floor, 0.01, 1e-15);
  EXPECT_EQ(prior.computed_from, 4);
  // κ before any choice: the grid value nearest p + 2 = 4.
  EXPECT_EQ(prior.pseudo_samples, 4.0);
}

TEST(CovariancePrior, FallsBackToTheSecondMomentWhileEverySampleIsOnePoint) {
  // One sample (3, 4): no spread, Ψ = (‖x̄‖²/p)·I = 12.5·I.
  Dataset data(2);
  data.Append(Eigen::Vector2d(3, 4), 1);
  const CovariancePrior prior = ComputeCovariancePrior(data, 1, CmmConfig{});
  EXPECT_TRUE(prior.scale.isApprox(12.5 * Eigen::Matrix2d::Identity(), 1e-15));
}

TEST(CovariancePrior, BackgroundIsTwiceTheSpreadOfAllTheData) {
  // Total covariance of the four samples: x: mean 5.5, deviations ±5.5, ±4.5 →
  // Σ(dx²)/3 = (30.25·2 + 20.25·2)/3 = 33.667; B = N(x̄, 4·(OAS(total) + φI)).
  const CovariancePrior prior = ComputeCovariancePrior(TwoPairs(), 4, CmmConfig{});
  double at_mean = 0.0;
  prior.BackgroundLogDensity(prior.background_mean.data(), 1, 1, &at_mean);
  EXPECT_NEAR(prior.background_mean[0], 5.5, 1e-15);
  EXPECT_NEAR(prior.background_mean[1], 5.5, 1e-15);
  // At its mean, log B = −½ log det(2π·Σ_B) < the log-density of a unit
  // Gaussian at its mean (−log 2π): B is broad.
  EXPECT_LT(at_mean, -std::log(2.0 * std::numbers::pi) - 3.0);
}

TEST(PooledPriorComponent, CovarianceIsTheMapEstimatePlusTheFloor) {
  // Samples (0, 0) and (2, 0) under Ψ = I, κ = 4, φ = 0.01: S = diag(2, 0),
  // Σ = (S + 4I)/(2 + 4) + 0.01·I = diag(1.01, 0.676667), so at the mean
  // log G = −log 2π − ½ log(1.01 · 0.676667).
  const Dataset data = TwoPairs();
  const CovariancePrior prior = ComputeCovariancePrior(data, 4, CmmConfig{});
  const std::vector<int> pair{0, 1};
  const Component c = Component::FromSamples(0, pair, data, CmmConfig{}, &prior);
  const double expected =
      -std::log(2.0 * std::numbers::pi) - 0.5 * std::log(1.01 * (4.0 / 6.0 + 0.01));
  EXPECT_NEAR(c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(Eigen::Vector2d(1, 0))),
              expected, 1e-12);
  // d² of (2, 0) from the mean (1, 0): 1/1.01.
  EXPECT_NEAR(c.SquaredMahalanobis(Eigen::Vector2d(2, 0)), 1.0 / 1.01, 1e-12);
}

TEST(PooledPriorComponent, LeaveOneOutEqualsTheComponentRebuiltWithoutTheSample) {
  // Without the floor the downdate is exact: the log-density of each sample
  // under the component of the other m − 1 samples, by Sherman–Morrison.
  Dataset data(3);
  Random random(5);
  for (int i = 0; i < 7; ++i) {
    data.Append(
        Eigen::Vector3d(random.UniformUnit(), 2 * random.UniformUnit(), random.UniformUnit()), 0);
  }
  CovariancePrior prior = ComputeCovariancePrior(data, 7, CmmConfig{});
  prior.floor = 0.0;
  std::vector<int> all{0, 1, 2, 3, 4, 5, 6};
  Component c = Component::FromSamples(0, all, data, CmmConfig{}, &prior);
  const auto column = c.LogDensityColumn(data);
  for (int j = 0; j < 7; ++j) {
    std::vector<int> others;
    for (int i : all) {
      if (i != j) others.push_back(i);
    }
    const Component without = Component::FromSamples(0, others, data, CmmConfig{}, &prior);
    const double direct =
        without.LogDensityFromSquaredDistance(without.SquaredMahalanobis(data.sample(j)));
    EXPECT_NEAR(c.LeaveOneOutLogDensity(column[j]), direct, 1e-9) << "sample " << j;
  }
}

TEST(PooledPriorComponent, LeaveOneOutOfASingleSampleIsMinusInfinity) {
  const Dataset data = TwoPairs();
  const CovariancePrior prior = ComputeCovariancePrior(data, 4, CmmConfig{});
  const std::vector<int> one{0};
  const Component c = Component::FromSamples(0, one, data, CmmConfig{}, &prior);
  EXPECT_EQ(c.LeaveOneOutLogDensity(0.0), -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace relmap::cmm
