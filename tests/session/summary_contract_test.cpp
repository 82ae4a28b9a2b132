// The store contract of session summaries: what ListSessions shows of a session
// without loading it (samples per label kept by the appends, the latest model
// summary a server recorded), for every store kind, and its migration.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "session/store_contract.h"

namespace relmap::session {
namespace {

using testing::MakeRecord;
using testing::SessionStoreSessions;

constexpr std::int64_t kCreatedMicros = 1'790'000'000'123'456;  // MakeRecord's

Timestamp At(std::int64_t unix_ms) { return Timestamp(std::chrono::milliseconds(unix_ms)); }

// The one listed session; a failure (and an empty summary) if there is not exactly one.
SessionSummary OnlyListed(SessionStore& store) {
  auto list = store.ListSessions();
  EXPECT_TRUE(list.ok()) << list.status().message();
  if (!list.ok() || list->size() != 1) {
    ADD_FAILURE() << "expected one listed session";
    return {};
  }
  return list->front();
}

TEST_P(SessionStoreSessions, SummaryCountsEveryStoredSampleByLabelOnce) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  const std::vector<double> x = {1, 2, 3};
  ASSERT_TRUE(store->AppendSample("a", "r1", x, 0).ok());
  ASSERT_TRUE(store->AppendSample("a", "r2", x, 1).ok());
  ASSERT_TRUE(store->AppendSample("a", "r3", x, 1).ok());
  ASSERT_TRUE(store->AppendSample("a", "r2", x, 1).ok());  // a retry: stores nothing
  EXPECT_EQ(store->AppendSample("a", "r4", x, 2).status().code(), StatusCode::kInvalidArgument);

  const SessionSummary summary = OnlyListed(*store);
  EXPECT_EQ(summary.samples[0], 1);
  EXPECT_EQ(summary.samples[1], 2);
  EXPECT_EQ(summary.sample_count(), 3);
  EXPECT_FALSE(summary.model.has_value());  // no server has recorded one
  EXPECT_FALSE(summary.model_current());
  EXPECT_EQ(summary.record.last_used.time_since_epoch().count(), kCreatedMicros);
}

TEST_P(SessionStoreSessions, ModelSummaryIsKeptUnlessTheKeptOneCoversMoreSamples) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  const std::vector<double> x = {1, 2, 3};
  for (const char* request : {"r1", "r2", "r3"}) {
    ASSERT_TRUE(store->AppendSample("a", request, x, 1).ok());
  }
  ASSERT_TRUE(store->RecordModelSummary("a", {2, {0, 1}, At(1'000)}).ok());
  SessionSummary summary = OnlyListed(*store);
  ASSERT_TRUE(summary.model.has_value());
  EXPECT_EQ(summary.model->sample_count, 2);
  EXPECT_FALSE(summary.model_current());  // 2 of the 3 stored samples

  ASSERT_TRUE(store->RecordModelSummary("a", {3, {0, 2}, At(1'500)}).ok());
  ASSERT_TRUE(store->RecordModelSummary("a", {3, {0, 2}, At(2'000)}).ok());  // a later call
  // A writer that learnt fewer samples, or as many before the last call (a stale
  // copy), does not undo it.
  ASSERT_TRUE(store->RecordModelSummary("a", {2, {5, 5}, At(3'000)}).ok());
  ASSERT_TRUE(store->RecordModelSummary("a", {3, {0, 2}, At(1'000)}).ok());
  summary = OnlyListed(*store);
  ASSERT_TRUE(summary.model_current());
  EXPECT_EQ(summary.model->components[0], 0);
  EXPECT_EQ(summary.model->components[1], 2);
  EXPECT_EQ(summary.model->last_used, At(2'000));
  EXPECT_EQ(store->LoadSession("a")->last_used, At(2'000));
}

TEST_P(SessionStoreSessions, ModelSummaryOfMoreSamplesThanStoredOrNegativeIsRefused) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  ASSERT_TRUE(store->AppendSample("a", "r1", std::vector<double>{1, 2, 3}, 0).ok());
  EXPECT_EQ(store->RecordModelSummary("a", {2, {1, 0}, At(1)}).code(),
            StatusCode::kFailedPrecondition);
  EXPECT_EQ(store->RecordModelSummary("a", {1, {-1, 0}, At(1)}).code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(store->RecordModelSummary("ghost", {0, {0, 0}, At(1)}).code(), StatusCode::kNotFound);
  EXPECT_FALSE(OnlyListed(*store).model.has_value());
}

TEST_P(SessionStoreSessions, ADeletedSessionLeavesNoSummaryToItsSuccessor) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());
  ASSERT_TRUE(store->AppendSample("a", "r1", std::vector<double>{1, 2, 3}, 1).ok());
  ASSERT_TRUE(store->RecordModelSummary("a", {1, {0, 1}, At(9'000)}).ok());
  ASSERT_TRUE(store->DeleteSession("a").ok());
  ASSERT_TRUE(store->CreateSession(MakeRecord("a")).ok());

  const SessionSummary summary = OnlyListed(*store);
  EXPECT_EQ(summary.samples[0], 0);
  EXPECT_EQ(summary.samples[1], 0);
  EXPECT_FALSE(summary.model.has_value());
  EXPECT_EQ(summary.record.last_used.time_since_epoch().count(), kCreatedMicros);
}

TEST_P(SessionStoreSessions, AStoreFromBeforeSummariesCountsItsSamplesWhenMigrated) {
  {
    auto store = OpenStore();
    ASSERT_TRUE(store->CreateSession(MakeRecord("old")).ok());
    ASSERT_TRUE(store->CreateSession(MakeRecord("empty")).ok());
    const std::vector<double> x = {1, 2, 3};
    ASSERT_TRUE(store->AppendSample("old", "r1", x, 0).ok());
    ASSERT_TRUE(store->AppendSample("old", "r2", x, 1).ok());
    ASSERT_TRUE(store->AppendSample("old", "r3", x, 1).ok());
    ASSERT_TRUE(store->RecordModelSummary("old", {3, {1, 1}, At(1)}).ok());
  }
  // The schema as version 2 left it: no summary columns.
  const std::string sqlite =
      std::string(testing::kSqliteDropSummaryColumns) + "UPDATE schema_version SET version = 2";
  const std::string postgres =
      std::string(testing::kPostgresDropSummaryColumns) + "UPDATE schema_version SET version = 2";
  ASSERT_TRUE(Tamper({sqlite.c_str(), postgres.c_str()}));

  auto store = OpenStore();
  auto list = store->ListSessions();
  ASSERT_TRUE(list.ok()) << list.status().message();
  ASSERT_EQ(list->size(), 2u);
  const SessionSummary& empty = (*list)[0];
  const SessionSummary& old = (*list)[1];
  EXPECT_EQ(empty.sample_count(), 0);
  EXPECT_EQ(old.samples[0], 1);
  EXPECT_EQ(old.samples[1], 2);
  // The model's components are not known until a server loads the session.
  EXPECT_FALSE(old.model.has_value());
  EXPECT_EQ(old.record.last_used.time_since_epoch().count(), kCreatedMicros);
  // Appends count on from the migrated counts (by a new instance: a shared store's
  // writer owns the session first).
  ASSERT_TRUE(store->AcquireOwnership("old").ok());
  ASSERT_TRUE(store->AppendSample("old", "r4", std::vector<double>{1, 2, 3}, 0).ok());
  EXPECT_EQ((*store->ListSessions())[1].samples[0], 2);
}

}  // namespace
}  // namespace relmap::session
