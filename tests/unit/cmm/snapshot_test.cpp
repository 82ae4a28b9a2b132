// Snapshots: a restored model predicts and learns bit for bit like the original;
// an inconsistent snapshot is refused with the reason.
#include "cmm/snapshot.h"

#include <gtest/gtest.h>

#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "support/cmm_training.h"

namespace relmap::cmm {
namespace {

using datasets::Problem;

void ExpectSameSnapshot(const CmmSnapshot& a, const CmmSnapshot& b) {
  EXPECT_EQ(a.features, b.features);
  EXPECT_EQ(a.labels, b.labels);
  EXPECT_EQ(a.random_state, b.random_state);
  EXPECT_EQ(a.splits, b.splits);
  EXPECT_EQ(a.merges, b.merges);
  for (int label = 0; label < 2; ++label) {
    ASSERT_EQ(a.components[label].size(), b.components[label].size());
    for (std::size_t k = 0; k < a.components[label].size(); ++k) {
      EXPECT_EQ(a.components[label][k].samples, b.components[label][k].samples);
      EXPECT_EQ(a.components[label][k].mean, b.components[label][k].mean);
      EXPECT_EQ(a.components[label][k].scatter, b.components[label][k].scatter);
      EXPECT_EQ(a.components[label][k].weight, b.components[label][k].weight);
    }
  }
}

class SnapshotRoundTrip : public ::testing::TestWithParam<Variant> {};

TEST_P(SnapshotRoundTrip, RestoredModelPredictsAndLearnsBitForBit) {
  const auto data = testing::Problem(Problem::kXorBlobs, 700, 8, 21);
  CmmConfig config = CmmConfig::ForVariant(GetParam());
  config.seed = 99;
  auto original = CollaborativeMixtureModels::Create(config, 8).value();
  testing::AddRows(original, data, 0, 400);
  ASSERT_GT(original.splits(), 0u);

  auto restored = CollaborativeMixtureModels::Restore(original.Snapshot());
  ASSERT_TRUE(restored.ok()) << restored.status().message();
  const Eigen::VectorXd before = original.Predict(data.features);
  const Eigen::VectorXd after = restored->Predict(data.features);
  EXPECT_TRUE((before.array() == after.array()).all());
  EXPECT_EQ(original.LogLikelihood(), restored->LogLikelihood());

  // Both go on learning from the same samples: same splits, merges and draws.
  testing::AddRows(original, data, 400, 700);
  testing::AddRows(*restored, data, 400, 700);
  ExpectSameSnapshot(original.Snapshot(), restored->Snapshot());
}

INSTANTIATE_TEST_SUITE_P(EveryVariant, SnapshotRoundTrip,
                         ::testing::Values(Variant::kCorrected, Variant::kCorrectedV1,
                                           Variant::kPaper2018),
                         [](const ::testing::TestParamInfo<Variant>& test_info) {
                           return std::string(VariantName(test_info.param));
                         });

class CorruptSnapshot : public ::testing::Test {
 protected:
  void SetUp() override {
    auto model = CollaborativeMixtureModels::Create(CmmConfig{}, 2).value();
    ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
    ASSERT_TRUE(model.Add(Eigen::Vector2d(1, 0), 1).ok());
    ASSERT_TRUE(model.Add(Eigen::Vector2d(5, 5), 0).ok());
    snapshot_ = model.Snapshot();
    ASSERT_TRUE(CollaborativeMixtureModels::Restore(snapshot_).ok());
  }
  StatusCode Code() const { return CollaborativeMixtureModels::Restore(snapshot_).status().code(); }
  CmmSnapshot snapshot_;
};

TEST_F(CorruptSnapshot, SampleInTwoComponentsIsDataLoss) {
  snapshot_.components[1].push_back(snapshot_.components[1][0]);
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, SampleWithoutComponentIsDataLoss) {
  snapshot_.components[0].clear();
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, SampleOfTheOtherClassIsDataLoss) {
  snapshot_.labels[2] = 1;
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, TruncatedFeaturesAreDataLoss) {
  snapshot_.features.pop_back();
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, NonFiniteFeatureIsDataLoss) {
  snapshot_.features[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, IndexOutOfRangeIsDataLoss) {
  snapshot_.components[0][0].samples = {7};
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, WrongScatterSizeIsDataLoss) {
  snapshot_.components[0][0].scatter.resize(3);
  EXPECT_EQ(Code(), StatusCode::kDataLoss);
}

TEST_F(CorruptSnapshot, InvalidConfigIsInvalidArgument) {
  snapshot_.config.alpha = 2.0;
  EXPECT_EQ(Code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::cmm
