// The session store contract: sessions, idempotent appends, exact samples,
// counters and schema versions, as the relevance server relies on them, for
// every store kind.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <fstream>
#include <limits>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "session/store_contract.h"

namespace relmap::session {
namespace {

using testing::MakeRecord;
using testing::SessionStoreSamples;
using testing::SessionStoreSessions;

TEST_P(SessionStoreSessions, LoadReturnsTheCreatedRecordFieldByField) {
  auto store = OpenStore();
  SessionRecord record = MakeRecord("alpha");
  record.cmm_config.alpha = 0.1;
  record.cmm_config.regularization = 3e-7;
  record.cmm_config.switches.skip_likelihood_check = true;
  record.cmm_config.switches.stale_weights = false;
  ASSERT_TRUE(store->CreateSession(record).ok());

  auto loaded = store->LoadSession("alpha");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  EXPECT_EQ(loaded->id, "alpha");
  EXPECT_EQ(loaded->token_hash, record.token_hash);
  EXPECT_EQ(loaded->created_at, record.created_at);
  EXPECT_EQ(loaded->config, record.config);
  EXPECT_EQ(loaded->cmm_config.variant, cmm::Variant::kPaper2018);
  EXPECT_EQ(loaded->cmm_config.alpha, 0.1);
  EXPECT_EQ(loaded->cmm_config.regularization, 3e-7);
  EXPECT_EQ(loaded->cmm_config.seed, 0xFEDCBA9876543210u);
  const cmm::Paper2018Switches& s = loaded->cmm_config.switches;
  EXPECT_TRUE(s.pseudo_density && s.first_sample_mean && s.nearest_candidate_only &&
              s.truncated_recheck && s.skip_likelihood_check);
  EXPECT_FALSE(s.stale_weights);
  EXPECT_EQ(loaded->feature_dimension, 3);
  EXPECT_EQ(loaded->counters.frames_computed, 0);
  EXPECT_EQ(loaded->counters.interactions, 0);
}

TEST_P(SessionStoreSessions, CreatingAnExistingIdIsAlreadyExists) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("alpha")).ok());
  const Status again = store->CreateSession(MakeRecord("alpha"));
  EXPECT_EQ(again.code(), StatusCode::kAlreadyExists);
  EXPECT_NE(again.message().find("alpha"), std::string::npos) << again.message();
}

TEST_P(SessionStoreSessions, InvalidRecordsAreRefused) {
  auto store = OpenStore();
  EXPECT_EQ(store->CreateSession(MakeRecord("")).code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(store->CreateSession(MakeRecord("flat", 0)).code(), StatusCode::kInvalidArgument);
  SessionRecord bad_alpha = MakeRecord("bad");
  bad_alpha.cmm_config.alpha = 2.0;
  EXPECT_EQ(store->CreateSession(bad_alpha).code(), StatusCode::kInvalidArgument);
}

TEST_P(SessionStoreSessions, UnknownSessionIsNotFoundEverywhere) {
  auto store = OpenStore();
  const std::vector<double> x = {1, 2, 3};
  EXPECT_EQ(store->LoadSession("ghost").status().code(), StatusCode::kNotFound);
  EXPECT_EQ(store->DeleteSession("ghost").code(), StatusCode::kNotFound);
  EXPECT_EQ(store->AppendSample("ghost", "r1", x, 1).status().code(), StatusCode::kNotFound);
  EXPECT_EQ(store->LoadSamples("ghost").status().code(), StatusCode::kNotFound);
  EXPECT_EQ(store->LoadLatestSnapshot("ghost").status().code(), StatusCode::kNotFound);
  EXPECT_EQ(store->IncrementCounters("ghost", {1, 1}).code(), StatusCode::kNotFound);
}

TEST_P(SessionStoreSessions, ListGivesIdsCreationTimesAndSampleCountsInIdOrder) {
  auto store = OpenStore();
  SessionRecord b = MakeRecord("b");
  b.created_at += std::chrono::microseconds(7);
  ASSERT_TRUE(store->CreateSession(b).ok());
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  const std::vector<double> x = {1, 2, 3};
  ASSERT_TRUE(store->AppendSample("b", "r1", x, 0).ok());
  ASSERT_TRUE(store->AppendSample("b", "r2", x, 1).ok());

  auto list = store->ListSessions();
  ASSERT_TRUE(list.ok()) << list.status().message();
  ASSERT_EQ(list->size(), 2u);
  EXPECT_EQ((*list)[0].record.id, "a");
  EXPECT_EQ((*list)[0].sample_count(), 0);
  EXPECT_EQ((*list)[1].record.id, "b");
  EXPECT_EQ((*list)[1].record.created_at, b.created_at);
  EXPECT_EQ((*list)[1].sample_count(), 2);
}

TEST_P(SessionStoreSessions, DeleteRemovesTheSessionWithItsSamplesAndSnapshot) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("alpha", 2)).ok());
  const std::vector<double> x = {0.5, -0.5};
  ASSERT_TRUE(store->AppendSample("alpha", "r1", x, 1).ok());
  auto model = cmm::CollaborativeMixtureModels::Create(cmm::CmmConfig{}, 2).value();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0.5, -0.5), 1).ok());
  ASSERT_TRUE(store->SaveSnapshot("alpha", model.Snapshot(), 1).ok());

  ASSERT_TRUE(store->DeleteSession("alpha").ok());
  EXPECT_EQ(store->LoadSession("alpha").status().code(), StatusCode::kNotFound);
  EXPECT_TRUE(store->ListSessions()->empty());
  // A new session under the same id starts empty: nothing of the old one is left.
  ASSERT_TRUE(store->CreateSession(MakeRecord("alpha", 2)).ok());
  EXPECT_TRUE(store->LoadSamples("alpha")->empty());
  EXPECT_FALSE(store->LoadLatestSnapshot("alpha")->has_value());
  EXPECT_EQ(*store->AppendSample("alpha", "r1", x, 0), 0);
}

TEST_P(SessionStoreSessions, CountersAddUp) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("alpha")).ok());
  ASSERT_TRUE(store->IncrementCounters("alpha", {.frames_computed = 2, .interactions = 0}).ok());
  ASSERT_TRUE(store->IncrementCounters("alpha", {.frames_computed = 1, .interactions = 5}).ok());
  EXPECT_EQ(store->IncrementCounters("alpha", {-1, 0}).code(), StatusCode::kInvalidArgument);
  const SessionCounters counters = store->LoadSession("alpha")->counters;
  EXPECT_EQ(counters.frames_computed, 3);
  EXPECT_EQ(counters.interactions, 5);
}

TEST_P(SessionStoreSamples, SequenceNumbersCountFromZeroInAppendOrder) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  ASSERT_TRUE(store->CreateSession(MakeRecord("b")).ok());
  const std::vector<double> x = {1, 2, 3};
  EXPECT_EQ(*store->AppendSample("a", "r1", x, 1), 0);
  EXPECT_EQ(*store->AppendSample("a", "r2", x, 0), 1);
  EXPECT_EQ(*store->AppendSample("b", "r1", x, 0), 0);  // numbering is per session
  EXPECT_EQ(*store->AppendSample("a", "r3", x, 1), 2);
}

TEST_P(SessionStoreSamples, RetriedRequestIdReturnsTheOriginalSequenceAndStoresNothing) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  const std::vector<double> x = {1, 2, 3};
  const std::vector<double> y = {4, 5, 6};
  ASSERT_EQ(*store->AppendSample("a", "first", x, 1), 0);
  ASSERT_EQ(*store->AppendSample("a", "second", y, 0), 1);

  auto retried = store->AppendSample("a", "first", x, 1);
  ASSERT_TRUE(retried.ok()) << retried.status().message();
  EXPECT_EQ(*retried, 0);
  EXPECT_EQ(store->LoadSamples("a")->size(), 2u);
  EXPECT_EQ(*store->AppendSample("a", "third", x, 1), 2);
}

TEST_P(SessionStoreSamples, RequestIdReusedWithDifferentContentIsFailedPrecondition) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  const std::vector<double> x = {1, 2, 3};
  const std::vector<double> x_changed = {1, 2, 3.0000000000000004};
  ASSERT_TRUE(store->AppendSample("a", "r1", x, 1).ok());

  const Status features = store->AppendSample("a", "r1", x_changed, 1).status();
  EXPECT_EQ(features.code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(features.message().find("reused with different content"), std::string::npos)
      << features.message();
  EXPECT_EQ(store->AppendSample("a", "r1", x, 0).status().code(), StatusCode::kFailedPrecondition);
  EXPECT_EQ(store->LoadSamples("a")->size(), 1u);
}

TEST_P(SessionStoreSamples, MalformedSamplesAreInvalidArguments) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  const std::vector<double> x = {1, 2, 3};
  const std::vector<double> short_x = {1, 2};
  const std::vector<double> nan_x = {1, std::numeric_limits<double>::quiet_NaN(), 3};
  EXPECT_EQ(store->AppendSample("a", "r", short_x, 1).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(store->AppendSample("a", "r", nan_x, 1).status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(store->AppendSample("a", "r", x, 2).status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(store->AppendSample("a", "", x, 1).status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(store->LoadSamples("a")->empty());
}

TEST_P(SessionStoreSamples, FeaturesComeBackBitForBitAfterReopening) {
  const std::vector<double> extremes = {
      -0.0,
      std::numeric_limits<double>::denorm_min(),
      -std::numeric_limits<double>::denorm_min() * 3,
      std::numeric_limits<double>::min() / 2,  // a denormal with a long mantissa
      1e308,
      -std::numeric_limits<double>::max(),
      0.1,
      1.0 + std::numeric_limits<double>::epsilon()};
  {
    auto store = OpenStore();
    ASSERT_TRUE(store->CreateSession(MakeRecord("a", 8)).ok());
    ASSERT_TRUE(store->AppendSample("a", "r1", extremes, 1).ok());
    const std::vector<double> zeros(8, 0.0);
    ASSERT_TRUE(store->AppendSample("a", "r2", zeros, 0).ok());
  }
  auto store = OpenStore();
  auto samples = store->LoadSamples("a");
  ASSERT_TRUE(samples.ok()) << samples.status().message();
  ASSERT_EQ(samples->size(), 2u);
  const StoredSample& first = (*samples)[0];
  EXPECT_EQ(first.sequence, 0);
  EXPECT_EQ(first.request_id, "r1");
  EXPECT_EQ(first.label, 1);
  ASSERT_EQ(first.features.size(), extremes.size());
  for (std::size_t k = 0; k < extremes.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(first.features[k]),
              std::bit_cast<std::uint64_t>(extremes[k]))
        << "feature " << k;
  }
  EXPECT_EQ((*samples)[1].sequence, 1);
  EXPECT_EQ((*samples)[1].label, 0);
}

TEST_P(SessionStoreSamples, FeatureBlobOfTheWrongLengthIsDataLoss) {
  {
    auto store = OpenStore();
    ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
    const std::vector<double> x = {1, 2, 3};
    ASSERT_TRUE(store->AppendSample("a", "r1", x, 1).ok());
  }
  // substr on a blob (SQLite) or bytea (PostgreSQL): its first 23 bytes.
  ASSERT_TRUE(Tamper({"UPDATE samples SET features = substr(features, 1, 23)",
                      "UPDATE samples SET features = substr(features, 1, 23)"}));
  auto store = OpenStore();
  const Status status = store->LoadSamples("a").status();
  EXPECT_EQ(status.code(), StatusCode::kDataLoss);
  EXPECT_NE(status.message().find("23-byte"), std::string::npos) << status.message();
}

TEST_P(SessionStoreSessions, ReopeningKeepsSessions) {
  {
    auto store = OpenStore();
    ASSERT_TRUE(store->CreateSession(MakeRecord("alpha")).ok());
  }
  auto store = OpenStore();
  EXPECT_TRUE(store->LoadSession("alpha").ok());
  EXPECT_EQ(store->CreateSession(MakeRecord("alpha")).code(), StatusCode::kAlreadyExists);
}

TEST_P(SessionStoreSessions, SchemaNewerThanThisBuildIsFailedPrecondition) {
  { OpenStore(); }
  ASSERT_TRUE(
      Tamper({"UPDATE schema_version SET version = 99", "UPDATE schema_version SET version = 99"}));
  auto store = TryOpenStore();
  ASSERT_FALSE(store.ok());
  EXPECT_EQ(store.status().code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(store.status().message().find("99"), std::string::npos) << store.status().message();
}

}  // namespace
}  // namespace relmap::session
