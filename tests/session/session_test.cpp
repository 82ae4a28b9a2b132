// Session through its C++ interface: learning raw features, the answers kept for
// retried requests, the frame cache, and the counters a restart restores.
#include "session/session.h"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "perception/synthetic_tabletop.h"
#include "session/feature_settings.h"

namespace relmap::session {
namespace {

// Sessions fed with feature vectors, not clouds, unless a test says otherwise.
using testing::FeatureSettings;
constexpr int kDimension = testing::kTestFeatureDimension;

std::unique_ptr<Session> NewSession(SessionSettings settings = FeatureSettings()) {
  auto session = Session::Create("s1", "hash", settings, 1000);
  EXPECT_TRUE(session.ok()) << session.status().message();
  return session.ok() ? std::move(session).value() : nullptr;
}

// `rows` feature vectors on the unit diagonal, the i-th scaled by i + 1.
Eigen::MatrixXd Diagonal(int rows) {
  Eigen::MatrixXd features(rows, kDimension);
  for (int i = 0; i < rows; ++i) features.row(i).setConstant(i + 1.0);
  return features;
}

// A small synthetic tabletop: a few hundred supervoxels, mapped in tens of ms.
perception::Cloud Tabletop(std::uint32_t seed = 1) {
  return perception::MakeSyntheticTabletop({.width = 120, .height = 90, .seed = seed}).cloud;
}

// The first supervoxel of a mapped frame whose features can be learned.
std::uint32_t Learnable(const MappedFrame& mapped) {
  const auto& features = mapped.frame->features.values;
  for (Eigen::Index row = 0; row < features.rows(); ++row) {
    if (features.row(row).allFinite()) return static_cast<std::uint32_t>(row);
  }
  ADD_FAILURE() << "frame " << mapped.frame_id << " has no learnable supervoxel";
  return 0;
}

TEST(Session, InvalidSettingsCreateNoSession) {
  SessionSettings settings = FeatureSettings();
  settings.feature_dimension = 0;
  EXPECT_EQ(Session::Create("s1", "hash", settings, 0).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(Session, CountsTheSamplesItLearnsPerLabel) {
  auto session = NewSession();
  auto stats = session->AddSamples(Diagonal(3), {1, 0, 1}, "r1", 2000);
  ASSERT_TRUE(stats.ok()) << stats.status().message();
  EXPECT_EQ(stats->samples[0], 1u);
  EXPECT_EQ(stats->samples[1], 2u);
  EXPECT_EQ(stats->created_unix_ms, 1000);
  EXPECT_EQ(stats->last_used_unix_ms, 2000);
}

TEST(Session, ARepeatedRequestIdIsAnsweredFromTheFirstAndLearnedOnce) {
  auto session = NewSession();
  ASSERT_TRUE(session->AddSamples(Diagonal(2), {1, 0}, "r1", 0).ok());
  auto again = session->AddSamples(Diagonal(3), {1, 1, 1}, "r1", 0);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->samples[0] + again->samples[1], 2u);
  EXPECT_EQ(session->Stats().samples[1], 1u);
}

TEST(Session, RequestsWithoutAnIdAreNeverTakenForRetries) {
  auto session = NewSession();
  ASSERT_TRUE(session->AddSamples(Diagonal(1), {1}, "", 0).ok());
  ASSERT_TRUE(session->AddSamples(Diagonal(1), {1}, "", 0).ok());
  EXPECT_EQ(session->Stats().samples[1], 2u);
}

TEST(Session, ABatchWithOneBadLabelLearnsNothing) {
  auto session = NewSession();
  EXPECT_EQ(session->AddSamples(Diagonal(2), {1, 2}, "r1", 0).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(session->Stats().samples[0] + session->Stats().samples[1], 0u);
  // The refused request's id stays free.
  EXPECT_TRUE(session->AddSamples(Diagonal(2), {1, 0}, "r1", 0).ok());
}

TEST(Session, FeaturesOfAnotherDimensionOrNotFiniteAreInvalid) {
  auto session = NewSession();
  EXPECT_EQ(session->ClassifyFeatures(Eigen::MatrixXd::Ones(1, kDimension + 1), 0).status().code(),
            StatusCode::kInvalidArgument);
  Eigen::MatrixXd infinite = Diagonal(1);
  infinite(0, 1) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(session->ClassifyFeatures(infinite, 0).status().code(), StatusCode::kInvalidArgument);
}

TEST(Session, ClassifyingLearnsNothingAndDrawsNoTarget) {
  auto session = NewSession();
  auto maps = session->ClassifyFeatures(Diagonal(4), 0);
  ASSERT_TRUE(maps.ok());
  EXPECT_EQ(maps->relevance.size(), 4);
  EXPECT_EQ(maps->target, -1);
  EXPECT_EQ(session->Stats().samples[0] + session->Stats().samples[1], 0u);
}

TEST(Session, AFeatureSessionCannotMapClouds) {
  auto session = NewSession();
  EXPECT_EQ(session->ComputeMaps(Tabletop(), 0).status().code(), StatusCode::kFailedPrecondition);
}

TEST(Session, AnOutcomeForAFrameNeverMappedIsAFailedPrecondition) {
  auto session = NewSession(SessionSettings{});
  EXPECT_EQ(session->PostOutcome(1, 0, 1, "r1", 0).status().code(),
            StatusCode::kFailedPrecondition);
}

TEST(Session, FramesAreNumberedFromOneAndOnlyTheCachedOnesTakeOutcomes) {
  auto session = NewSession(SessionSettings{});
  session->set_policy({.frame_cache = 2});
  std::vector<std::uint32_t> learnable;
  for (std::uint64_t want = 1; want <= 3; ++want) {
    auto mapped = session->ComputeMaps(Tabletop(static_cast<std::uint32_t>(want)), 0);
    ASSERT_TRUE(mapped.ok()) << mapped.status().message();
    EXPECT_EQ(mapped->frame_id, want);
    learnable.push_back(Learnable(*mapped));
  }
  // The cache of 2 holds frames 2 and 3; frame 1 was evicted first.
  EXPECT_EQ(session->PostOutcome(1, learnable[0], 1, "r1", 0).status().code(),
            StatusCode::kFailedPrecondition);
  EXPECT_TRUE(session->PostOutcome(2, learnable[1], 1, "r2", 0).ok());
  EXPECT_TRUE(session->PostOutcome(3, learnable[2], 0, "r3", 0).ok());
  EXPECT_EQ(session->Stats().frames, 3u);
}

TEST(Session, ASmallerCacheEvictsTheOldestFramesAtOnce) {
  auto session = NewSession(SessionSettings{});
  auto first = session->ComputeMaps(Tabletop(1), 0);
  auto second = session->ComputeMaps(Tabletop(2), 0);
  ASSERT_TRUE(first.ok() && second.ok());
  session->set_policy({.frame_cache = 1});
  EXPECT_EQ(session->PostOutcome(1, Learnable(*first), 1, "r1", 0).status().code(),
            StatusCode::kFailedPrecondition);
  EXPECT_TRUE(session->PostOutcome(2, Learnable(*second), 1, "r2", 0).ok());
}

TEST(Session, ARepeatedOutcomeReturnsTheFirstAnswerWhateverItCarries) {
  auto session = NewSession(SessionSettings{});
  auto mapped = session->ComputeMaps(Tabletop(), 0);
  ASSERT_TRUE(mapped.ok());
  auto first = session->PostOutcome(mapped->frame_id, Learnable(*mapped), 1, "r1", 0);
  ASSERT_TRUE(first.ok());
  auto again = session->PostOutcome(mapped->frame_id, Learnable(*mapped) + 1, 0, "r1", 0);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->label, 1);
  EXPECT_EQ(session->Stats().samples[0] + session->Stats().samples[1], 1u);
}

TEST(Session, ASupervoxelPastTheFramesLastIsInvalid) {
  auto session = NewSession(SessionSettings{});
  auto mapped = session->ComputeMaps(Tabletop(), 0);
  ASSERT_TRUE(mapped.ok());
  const auto past = static_cast<std::uint32_t>(mapped->frame->size());
  EXPECT_EQ(session->PostOutcome(mapped->frame_id, past, 1, "r1", 0).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(Session, RestoredCountersContinueTheFrameIds) {
  auto session = NewSession(SessionSettings{});
  session->RestoreCounters(5, 0);
  auto mapped = session->ComputeMaps(Tabletop(), 0);
  ASSERT_TRUE(mapped.ok());
  EXPECT_EQ(mapped->frame_id, 6u);
  EXPECT_EQ(session->Stats().frames, 6u);
  // Frame 5 belonged to the previous life: never matched with a new frame.
  EXPECT_EQ(session->PostOutcome(5, 0, 1, "r1", 0).status().code(),
            StatusCode::kFailedPrecondition);
}

TEST(Session, AnExportedStateImportsIntoANewSessionAsItWas) {
  auto original = NewSession();
  ASSERT_TRUE(original->AddSamples(Diagonal(3), {1, 0, 1}, "r1", 0).ok());
  const SessionState exported = original->ExportState();
  auto copy = NewSession();
  ASSERT_TRUE(copy->ImportState(exported, 0).ok());
  const SessionState reexported = copy->ExportState();
  EXPECT_EQ(reexported.features, exported.features);
  EXPECT_EQ(reexported.labels, exported.labels);
  EXPECT_EQ(reexported.target_random, exported.target_random);
  // Only into an empty session.
  EXPECT_EQ(copy->ImportState(exported, 0).status().code(), StatusCode::kFailedPrecondition);
}

}  // namespace
}  // namespace relmap::session
