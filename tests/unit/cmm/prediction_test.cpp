// The paper's prediction, eq. (class_est): P(L=1|x) = (1 + Γ1(x)) / (2 + Γ0(x) + Γ1(x))
// (Prediction::kPseudoCount, as corrected_v1 and paper2018 predict).
#include <gtest/gtest.h>

#include <cmath>

#include "cmm/collaborative_mixture_models.h"
#include "support/cmm_training.h"

namespace relmap::cmm {
namespace {

const CmmConfig kPseudoCount = CmmConfig::ForVariant(Variant::kCorrectedV1);

CollaborativeMixtureModels Empty2d() {
  return CollaborativeMixtureModels::Create(kPseudoCount, 2).value();
}

TEST(Prediction, IsOneHalfWithoutAnyComponent) {
  const auto model = Empty2d();
  const Eigen::MatrixXd points = Eigen::MatrixXd::Random(5, 2);
  EXPECT_TRUE(model.Predict(points).isApproxToConstant(0.5, 0.0));
}

TEST(Prediction, OneMoveableSampleGivesTheUnitGaussianDensity) {
  // One class-1 sample at 0: Γ1(0) = G(0; 0, I) = 1/(2π) = 0.159155,
  // P = 1.159155 / 2.159155 = 0.536855.
  auto model = Empty2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  const Eigen::MatrixXd at_origin = Eigen::RowVector2d(0, 0);
  EXPECT_NEAR(model.Predict(at_origin)[0], 0.536855, 1e-6);
}

TEST(Prediction, TwoClassesWeighTheirDensities) {
  // Class 1 at (0,0), class 0 at (3,0). At the origin Γ1 = 1/(2π) = 0.159155 and
  // Γ0 = e^{−4.5}/(2π) = 0.0017680: P = 1.159155 / 2.160923 = 0.5364166.
  auto model = Empty2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  ASSERT_TRUE(model.Add(Eigen::Vector2d(3, 0), 0).ok());
  const Eigen::MatrixXd at_origin = Eigen::RowVector2d(0, 0);
  EXPECT_NEAR(model.Predict(at_origin)[0], 0.5364166, 1e-6);
}

TEST(Prediction, SumsWeightedComponentsOfAClass) {
  // Two class-1 components of one sample each, at (0,0) and (2,0), weights ½.
  // At (1,0): each G = e^{−0.5}/(2π) = 0.0965324, Γ1 = 0.0965324,
  // P = 1.0965324 / 2.0965324 = 0.523021.
  CmmSnapshot snapshot;
  snapshot.config = kPseudoCount;
  snapshot.dimension = 2;
  snapshot.features = {0, 0, 2, 0};
  snapshot.labels = {1, 1};
  snapshot.components[1] = {ComponentSnapshot{{0}, {0, 0}, {0, 0, 0, 0}, 0.5},
                            ComponentSnapshot{{1}, {2, 0}, {0, 0, 0, 0}, 0.5}};
  const auto model = CollaborativeMixtureModels::Restore(snapshot);
  ASSERT_TRUE(model.ok()) << model.status().message();
  const Eigen::MatrixXd between = Eigen::RowVector2d(1, 0);
  EXPECT_NEAR(model->Predict(between)[0], 0.523021, 1e-6);
}

TEST(Prediction, TendsToOneHalfFarFromAllData) {
  auto model = Empty2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  const Eigen::MatrixXd far = Eigen::RowVector2d(100, 100);
  EXPECT_DOUBLE_EQ(model.Predict(far)[0], 0.5);
}

TEST(Prediction, DoesNotUnderflowIn48d) {
  // Tight 48-d components have densities far beyond the range of a double
  // (log-normaliser ≈ +300); the log domain keeps the prediction exact.
  const auto train = testing::Problem(datasets::Problem::kTwoMoons, 400, 48, 4);
  const auto model = testing::Train(train, kPseudoCount);
  const Eigen::VectorXd p = model.Predict(train.features);
  ASSERT_TRUE(p.allFinite());
  int right = 0;
  for (int i = 0; i < p.size(); ++i) right += (p[i] > 0.5) == (train.labels[i] == 1) ? 1 : 0;
  EXPECT_GT(right, 390);
}

TEST(Prediction, WeightsAreSizeProportionalAndSumToOne) {
  const auto train = testing::Problem(datasets::Problem::kXorBlobs, 500, 2, 5);
  const auto model = testing::Train(train, kPseudoCount);
  for (int label = 0; label < 2; ++label) {
    double total = 0.0;
    for (const Component& c : model.components(label)) {
      EXPECT_DOUBLE_EQ(c.weight(), c.size() / static_cast<double>(model.sample_count(label)));
      total += c.weight();
    }
    EXPECT_NEAR(total, 1.0, 1e-12);
  }
}

TEST(LogLikelihood, IsTheSumOfLogPredictionsOfTheLabels) {
  const auto train = testing::Problem(datasets::Problem::kTwoMoons, 300, 2, 6);
  auto model = testing::Train(train, kPseudoCount);
  const Eigen::VectorXd p = model.Predict(train.features);
  double expected = 0.0;
  for (int i = 0; i < p.size(); ++i) expected += std::log(train.labels[i] == 1 ? p[i] : 1.0 - p[i]);
  EXPECT_NEAR(model.LogLikelihood(), expected, 1e-9 * std::abs(expected));
}

TEST(Evaluation, ReportsTheNearestComponentDistanceAndMembership) {
  auto model = Empty2d();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  ASSERT_TRUE(model.Add(Eigen::Vector2d(3, 0), 0).ok());
  Eigen::MatrixXd points(2, 2);
  points << 1, 0, 3, 2;
  const Evaluation e = model.Evaluate(points);
  EXPECT_DOUBLE_EQ(e.nearest_squared_mahalanobis[0], 1.0);
  EXPECT_DOUBLE_EQ(e.nearest_squared_mahalanobis[1], 4.0);
  // One component per class: membership within its class is 1.
  EXPECT_NEAR(e.nearest_log_membership[0], 0.0, 1e-15);
}

TEST(Evaluation, HasNoNearestComponentInAnEmptyModel) {
  const auto model = Empty2d();
  const Evaluation e = model.Evaluate(Eigen::MatrixXd::Zero(3, 2));
  EXPECT_TRUE(std::isinf(e.nearest_squared_mahalanobis[0]));
  EXPECT_TRUE(std::isinf(e.nearest_log_membership[0]));
}

}  // namespace
}  // namespace relmap::cmm
