// Densities and running statistics of one component (§3.1, §3.2), against
// hand-computed values and closed forms.
#include "cmm/component.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <numeric>

#include "common/random.h"

namespace relmap::cmm {
namespace {

const double kLogTwoPi = std::log(2.0 * std::numbers::pi);

Dataset MakeDataset(std::initializer_list<std::vector<double>> rows) {
  Dataset data(static_cast<int>(rows.begin()->size()));
  for (const auto& row : rows)
    data.Append(
        Eigen::Map<const Eigen::VectorXd>(row.data(), static_cast<Eigen::Index>(row.size())), 0);
  return data;
}

std::vector<int> AllIndices(const Dataset& data) {
  std::vector<int> indices(data.size());
  std::iota(indices.begin(), indices.end(), 0);
  return indices;
}

// log N(x; μ, Σ) by the textbook formula, with a dense inverse and determinant.
double ClosedFormLogDensity(const Eigen::VectorXd& x, const Eigen::VectorXd& mu,
                            const Eigen::MatrixXd& sigma) {
  const Eigen::VectorXd d = x - mu;
  const auto p = static_cast<double>(x.size());
  return -0.5 * d.dot(sigma.inverse() * d) - 0.5 * std::log(sigma.determinant()) -
         0.5 * p * kLogTwoPi;
}

TEST(Component, LogDensityMatchesTheHandComputedValueIn2d) {
  // Samples (±1, 0), (0, ±2): μ = 0, scatter diag(2, 8), Σ = diag(2/3, 8/3).
  // At x = (1, 2): d² = 1/(2/3) + 4/(8/3) = 3, log det(2πΣ) = 2 log 2π + log(16/9),
  // log G = −1.5 − log 2π − ½ log(16/9) = −3.625559.
  const Dataset data = MakeDataset({{-1, 0}, {1, 0}, {0, -2}, {0, 2}});
  CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  config.regularization = 1e-12;
  const Component c = Component::FromSamples(0, AllIndices(data), data, config);
  const Eigen::Vector2d x(1, 2);
  EXPECT_NEAR(c.SquaredMahalanobis(x), 3.0, 1e-9);
  EXPECT_NEAR(c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(x)), -3.625559, 1e-6);
  EXPECT_EQ(c.shape(), Component::Shape::kGaussian);
}

TEST(Component, LogDensityMatchesTheClosedFormIn48d) {
  Random random(17);
  Dataset data(48);
  for (int i = 0; i < 120; ++i) {
    Eigen::VectorXd x(48);
    for (int k = 0; k < 48; ++k) x[k] = 0.1 * random.UniformUnit() + 0.01 * k;
    data.Append(x, 1);
  }
  const CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);  // λ = 1e-6
  const Component c = Component::FromSamples(1, AllIndices(data), data, config);
  Eigen::MatrixXd sigma = c.scatter() / 119.0;
  sigma.diagonal().array() += 1e-6;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd x(48);
    for (int k = 0; k < 48; ++k) x[k] = 0.1 * random.UniformUnit() + 0.01 * k;
    const double expected = ClosedFormLogDensity(x, c.mean(), sigma);
    const double actual = c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(x));
    EXPECT_NEAR(actual, expected, 1e-8 * std::abs(expected));
  }
}

TEST(Component, SingleSampleUsesTheUnitCovariance) {
  // G(s, I): log G(x) = −‖x − s‖²/2 − (p/2) log 2π.
  const Dataset data = MakeDataset({{1, 2, 3}});
  const Component c =
      Component::FromSamples(0, {{0}}, data, CmmConfig::ForVariant(Variant::kCorrectedV1));
  const Eigen::Vector3d x(1, 2, 5);
  EXPECT_EQ(c.shape(), Component::Shape::kUnit);
  EXPECT_DOUBLE_EQ(c.SquaredMahalanobis(x), 4.0);
  EXPECT_NEAR(c.LogDensityFromSquaredDistance(4.0), -2.0 - 1.5 * kLogTwoPi, 1e-12);
}

TEST(Component, OnlineUpdatesMatchBatchStatistics) {
  // 150 samples: the batch scatter is summed over two full blocks of 64 and a partial one.
  Random random(3);
  Dataset data(5);
  for (int i = 0; i < 150; ++i) {
    Eigen::VectorXd x(5);
    for (int k = 0; k < 5; ++k) x[k] = random.UniformUnit() * (k + 1);
    data.Append(x, 0);
  }
  const CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  Component online = Component::FromSamples(0, {{0}}, data, config);
  for (int i = 1; i < 150; ++i) online.AddSample(i, data, config);
  const Component batch = Component::FromSamples(0, AllIndices(data), data, config);
  EXPECT_TRUE(online.mean().isApprox(batch.mean(), 1e-12));
  EXPECT_TRUE(online.scatter().isApprox(batch.scatter(), 1e-12));
  EXPECT_EQ(online.indices(), batch.indices());
}

TEST(Component, UnionMatchesBatchStatistics) {
  const Dataset data = MakeDataset({{0, 0}, {1, 0}, {0, 1}, {5, 5}, {6, 5}, {5, 7}});
  const CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  const Component a = Component::FromSamples(0, {{0, 1, 2}}, data, config);
  const Component b = Component::FromSamples(0, {{3, 4, 5}}, data, config);
  const Component u = Component::Union(a, b, data, config);
  const Component all = Component::FromSamples(0, AllIndices(data), data, config);
  EXPECT_TRUE(u.mean().isApprox(all.mean(), 1e-12));
  EXPECT_TRUE(u.scatter().isApprox(all.scatter(), 1e-12));
  EXPECT_EQ(u.indices(), all.indices());
}

TEST(Component, BatchDistancesEqualSinglePointDistancesBitForBit) {
  Random random(8);
  Dataset data(48);
  for (int i = 0; i < 70; ++i) {
    Eigen::VectorXd x(48);
    for (int k = 0; k < 48; ++k) x[k] = random.UniformUnit();
    data.Append(x, 0);
  }
  const Component c = Component::FromSamples(0, AllIndices(data), data,
                                             CmmConfig::ForVariant(Variant::kCorrectedV1));
  std::vector<double> batch(70);
  c.SquaredMahalanobis(data.data(), 70, data.stride(), batch.data());
  for (int i = 0; i < 70; ++i) EXPECT_EQ(batch[i], c.SquaredMahalanobis(data.sample(i)));
}

TEST(Component, PaperDensityOfASmallComponentIsAHitAtItsFirstSample) {
  // paper2018: m <= 4 → μ = first sample, density 1 within ‖x − μ‖² < 1e-4, else 0.
  const Dataset data = MakeDataset({{0, 0}, {2, 0}, {4, 0}});
  const CmmConfig config = CmmConfig::ForVariant(Variant::kPaper2018);
  const Component c = Component::FromSamples(0, AllIndices(data), data, config);
  EXPECT_EQ(c.shape(), Component::Shape::kHit);
  EXPECT_EQ(c.centre(), Eigen::Vector2d(0, 0));
  EXPECT_EQ(c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(Eigen::Vector2d(0.005, 0))), 0.0);
  EXPECT_TRUE(
      std::isinf(c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(Eigen::Vector2d(0.02, 0)))));
}

TEST(Component, PaperDensityUsesPseudoInverseAndPseudoDeterminantWithoutRoot) {
  // Samples (±1,0,0), (0,±2,0), (0,0,0): Σ = scatter/4 = diag(0.5, 2, 0). The
  // zero singular value is dropped: at x = (1, 2, 5), d² = 1/0.5 + 4/2 = 4, and
  // log G = −d²/2 − log(2π·0.5) − log(2π·2) = −2 − log π − log 4π = −5.675754.
  const Dataset data = MakeDataset({{-1, 0, 0}, {1, 0, 0}, {0, -2, 0}, {0, 2, 0}, {0, 0, 0}});
  const CmmConfig config = CmmConfig::ForVariant(Variant::kPaper2018);
  const Component c = Component::FromSamples(0, AllIndices(data), data, config);
  const Eigen::Vector3d x(1, 2, 5);
  EXPECT_EQ(c.shape(), Component::Shape::kGaussian);
  EXPECT_NEAR(c.SquaredMahalanobis(x), 4.0, 1e-12);
  EXPECT_NEAR(c.LogDensityFromSquaredDistance(4.0), -5.675754, 1e-6);
}

TEST(Component, LogDensityColumnFollowsTheDatasetAndResetsOnChange) {
  Dataset data = MakeDataset({{0, 0}, {1, 0}, {0, 1}});
  const CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  Component c = Component::FromSamples(0, {{0, 1, 2}}, data, config);
  EXPECT_EQ(c.LogDensityColumn(data).size(), 3u);
  data.Append(Eigen::Vector2d(3, 3), 0);
  const auto column = c.LogDensityColumn(data);
  ASSERT_EQ(column.size(), 4u);
  EXPECT_EQ(column[3], c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(data.sample(3))));
  c.AddSample(3, data, config);
  EXPECT_EQ(c.LogDensityColumn(data)[0],
            c.LogDensityFromSquaredDistance(c.SquaredMahalanobis(data.sample(0))));
}

TEST(Component, SplitProposalIsForgottenWhenTheComponentChanges) {
  Dataset data = MakeDataset({{0, 0}, {1, 0}, {0, 1}, {3, 3}});
  const CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  Component c = Component::FromSamples(0, {{0, 1, 2}}, data, config);
  EXPECT_FALSE(c.cached_split().has_value());  // nothing proposed yet
  c.cached_split() = std::vector<Component>{};
  Component copy = c;  // a copy keeps the proposal: same samples, same halves
  EXPECT_TRUE(copy.cached_split().has_value());
  c.AddSample(3, data, config);  // other samples: the halves would differ
  EXPECT_FALSE(c.cached_split().has_value());
}

}  // namespace
}  // namespace relmap::cmm
