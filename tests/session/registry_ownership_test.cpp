// The registry against a store shared by several servers (a GMock SessionStore):
// when it asks the store for a session's ownership, and what it does with the answer.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "session/registry/session_registry.h"

namespace relmap::session {
namespace {

using ::testing::_;
using ::testing::Return;

class SharedStore : public SessionStore {
 public:
  MOCK_METHOD(Status, CreateSession, (const SessionRecord&), (override));
  MOCK_METHOD(StatusOr<SessionRecord>, LoadSession, (std::string_view), (override));
  MOCK_METHOD(StatusOr<std::vector<SessionSummary>>, ListSessions, (), (override));
  MOCK_METHOD(Status, DeleteSession, (std::string_view), (override));
  MOCK_METHOD(StatusOr<std::int64_t>, AppendSample,
              (std::string_view, std::string_view, std::span<const double>, int), (override));
  MOCK_METHOD(StatusOr<std::vector<StoredSample>>, LoadSamples, (std::string_view), (override));
  MOCK_METHOD(Status, SaveSnapshot, (std::string_view, const cmm::CmmSnapshot&, std::int64_t),
              (override));
  MOCK_METHOD(StatusOr<std::optional<StoredSnapshot>>, LoadLatestSnapshot, (std::string_view),
              (override));
  MOCK_METHOD(Status, IncrementCounters, (std::string_view, const SessionCounters&), (override));
  MOCK_METHOD(Status, RecordModelSummary, (std::string_view, const ModelSummary&), (override));
  MOCK_METHOD(StatusOr<Ownership>, AcquireOwnership, (std::string_view), (override));
  MOCK_METHOD(void, ReleaseOwnership, (std::string_view), (override));
};

StatusOr<SessionStore::Ownership> Held(bool throughout) {
  return SessionStore::Ownership{.held_throughout = throughout};
}

class RegistryOwnership : public ::testing::Test {
 protected:
  RegistryOwnership() : registry_(10, &store_) {
    ON_CALL(store_, CreateSession(_)).WillByDefault(Return(OkStatus()));
    ON_CALL(store_, AcquireOwnership(_)).WillByDefault([this](std::string_view) {
      ++acquisitions_;
      return Held(true);
    });
    registry_.set_loader([this](const std::string& id) -> StatusOr<std::shared_ptr<Session>> {
      ++loads_;
      acquisitions_when_loaded_ = acquisitions_;
      auto loaded = Session::Create(id, "hash", SessionSettings{}, 0, &store_);
      if (!loaded.ok()) return loaded.status();
      return std::shared_ptr<Session>(std::move(loaded).value());
    });
  }
  std::string CreateOne() {
    auto created = registry_.Create(SessionSettings{}, "config", 0);
    EXPECT_TRUE(created.ok());
    return created.ok() ? created->session->id() : "";
  }

  ::testing::NiceMock<SharedStore> store_;
  SessionRegistry registry_;
  int loads_ = 0;
  int acquisitions_ = 0;
  int acquisitions_when_loaded_ = -1;
};

TEST_F(RegistryOwnership, AResidentSessionHeldThroughoutIsServedFromMemory) {
  const std::string id = CreateOne();
  EXPECT_CALL(store_, AcquireOwnership(std::string_view(id))).WillOnce(Return(Held(true)));
  auto found = registry_.Find(id);
  ASSERT_TRUE(found.ok());
  EXPECT_EQ(loads_, 0);
}

TEST_F(RegistryOwnership, AResidentSessionAnotherServerHadMeanwhileIsLoadedAnew) {
  const std::string id = CreateOne();
  auto before = registry_.Find(id);  // held throughout, by default
  ASSERT_TRUE(before.ok());
  EXPECT_CALL(store_, AcquireOwnership(std::string_view(id)))
      .WillOnce(Return(Held(false)))  // taken back from another server: memory is stale
      .WillOnce(Return(Held(true)));  // the hold the load runs under
  auto after = registry_.Find(id);
  ASSERT_TRUE(after.ok());
  EXPECT_EQ(loads_, 1);
  EXPECT_NE(after->get(), before->get());
}

TEST_F(RegistryOwnership, ASessionOwnedByAnotherLiveServerIsUnavailableAndLeavesMemory) {
  const std::string id = CreateOne();
  EXPECT_CALL(store_, AcquireOwnership(std::string_view(id)))
      .WillOnce(Return(Status(StatusCode::kUnavailable, "owned by server b")));
  auto found = registry_.Find(id);
  EXPECT_EQ(found.status().code(), StatusCode::kUnavailable);
  EXPECT_TRUE(registry_.Resident().empty()) << "a stale copy must not stay in memory";
}

TEST_F(RegistryOwnership, ASessionNotInMemoryIsOwnedBeforeItIsLoaded) {
  auto found = registry_.Find("abc");
  ASSERT_TRUE(found.ok());
  EXPECT_EQ(loads_, 1);
  EXPECT_EQ(acquisitions_when_loaded_, 1) << "read while another server could still append";
}

TEST_F(RegistryOwnership, ASessionNotInMemoryOwnedElsewhereIsNotLoaded) {
  EXPECT_CALL(store_, AcquireOwnership(std::string_view("abc")))
      .WillOnce(Return(Status(StatusCode::kUnavailable, "owned by server b")));
  EXPECT_EQ(registry_.Find("abc").status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(loads_, 0);
}

TEST_F(RegistryOwnership, AnUnknownSessionIsNotFound) {
  EXPECT_CALL(store_, AcquireOwnership(std::string_view("abc")))
      .WillOnce(Return(Status(StatusCode::kNotFound, "no row")));
  EXPECT_EQ(registry_.Find("abc").status().code(), StatusCode::kNotFound);
}

TEST_F(RegistryOwnership, HandOverReleasesTheSessionAndKeepsItInMemory) {
  const std::string id = CreateOne();
  EXPECT_CALL(store_, ReleaseOwnership(std::string_view(id)));
  registry_.HandOver(id);
  EXPECT_EQ(registry_.Resident().size(), 1u);
}

TEST_F(RegistryOwnership, EvictedAndReleasedSessionsAreGivenUp) {
  const std::string first = CreateOne();
  const std::string second = CreateOne();
  EXPECT_CALL(store_, ReleaseOwnership(std::string_view(first)));
  EXPECT_CALL(store_, ReleaseOwnership(std::string_view(second)));
  EXPECT_EQ(registry_.EvictIdle(1).size(), 2u);  // last used at 0 < 1
  EXPECT_TRUE(registry_.Resident().empty());
}

TEST_F(RegistryOwnership, ReleaseAllGivesUpEverySessionInMemory) {
  const std::string id = CreateOne();
  EXPECT_CALL(store_, ReleaseOwnership(std::string_view(id)));
  registry_.ReleaseAll();
  EXPECT_TRUE(registry_.Resident().empty());
}

TEST_F(RegistryOwnership, ListingReadsStoredSessionsWithoutTakingOrKeepingThem) {
  std::vector<SessionSummary> stored(2);
  stored[0].record.id = "a";
  stored[1].record.id = "b";
  EXPECT_CALL(store_, ListSessions()).WillOnce(Return(stored));
  EXPECT_CALL(store_, AcquireOwnership(_)).Times(0);
  const SessionRegistry::Page page = registry_.List("", 10);
  EXPECT_EQ(page.sessions.size(), 2u);
  EXPECT_EQ(loads_, 2);
  EXPECT_TRUE(registry_.Resident().empty());
}

}  // namespace
}  // namespace relmap::session
