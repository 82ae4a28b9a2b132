// SessionRegistry through its C++ interface: creation within the limit, lookup and
// deletion, pages in id order, and sessions restored from a store on their first
// call after eviction.
#include "session/registry/session_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "session/credentials.h"
#include "session/feature_settings.h"
#include "session/registry/session_listing.h"
#include "session/registry/session_restore.h"
#include "session/store/sqlite/sqlite_session_store.h"
#include "session/store_test_support.h"

namespace relmap::session {
namespace {

// Sessions fed with feature vectors, not clouds, unless a test says otherwise.
using testing::FeatureSettings;
constexpr int kDimension = testing::kTestFeatureDimension;

std::string CreateOne(SessionRegistry& registry) {
  auto created = registry.Create(FeatureSettings(), "config", 0);
  EXPECT_TRUE(created.ok()) << created.status().message();
  return created.ok() ? created->session->id() : "";
}

TEST(SessionRegistry, ACreatedSessionIsFoundByItsIdAndItsTokenMatches) {
  SessionRegistry registry(4);
  auto created = registry.Create(FeatureSettings(), "config", 0);
  ASSERT_TRUE(created.ok());
  auto found = registry.Find(created->session->id());
  ASSERT_TRUE(found.ok());
  EXPECT_EQ(found->get(), created->session.get());
  EXPECT_TRUE(TokenMatches(created->token, (*found)->token_hash()));
  EXPECT_NE((*found)->token_hash(), created->token);  // the registry keeps the hash only
}

TEST(SessionRegistry, AnUnknownIdIsNotFound) {
  SessionRegistry registry(4);
  EXPECT_EQ(registry.Find("nobody").status().code(), StatusCode::kNotFound);
  EXPECT_EQ(registry.Delete("nobody").code(), StatusCode::kNotFound);
}

TEST(SessionRegistry, ADeletedSessionIsNotFound) {
  SessionRegistry registry(4);
  const std::string id = CreateOne(registry);
  ASSERT_TRUE(registry.Delete(id).ok());
  EXPECT_EQ(registry.Find(id).status().code(), StatusCode::kNotFound);
  EXPECT_TRUE(registry.Resident().empty());
}

TEST(SessionRegistry, TheLimitIsResourceExhaustedUntilASessionIsDeleted) {
  SessionRegistry registry(2);
  const std::string first = CreateOne(registry);
  CreateOne(registry);
  EXPECT_EQ(registry.Create(FeatureSettings(), "config", 0).status().code(),
            StatusCode::kResourceExhausted);
  ASSERT_TRUE(registry.Delete(first).ok());
  EXPECT_TRUE(registry.Create(FeatureSettings(), "config", 0).ok());
}

// The server sizes its worker pool by what the observer hears.
TEST(SessionRegistry, TheSizeObserverHearsEveryChangeInOrder) {
  SessionRegistry registry(4);
  std::vector<std::size_t> sizes;
  registry.set_size_observer([&](std::size_t n) { sizes.push_back(n); });
  const std::string first = CreateOne(registry);
  CreateOne(registry);
  ASSERT_TRUE(registry.Delete(first).ok());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{0, 1, 2, 1}));  // told at once, then each change
}

TEST(SessionRegistry, InvalidSettingsCreateNothing) {
  SessionRegistry registry(2);
  SessionSettings settings = FeatureSettings();
  settings.feature_dimension = 0;
  EXPECT_EQ(registry.Create(settings, "config", 0).status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(registry.Resident().empty());
}

TEST(SessionRegistry, GivesEveryNewSessionItsPolicy) {
  SessionRegistry registry(2);
  registry.set_policy({.frame_cache = 1});
  auto created = registry.Create(SessionSettings{}, "config", 0);
  ASSERT_TRUE(created.ok());
  // Seen through the cache: an unknown frame's message names its size.
  EXPECT_NE(created->session->PostOutcome(1, 0, 1, "r", 0).status().message().find("last 1 frames"),
            std::string::npos);
}

TEST(SessionRegistry, WithoutAStoreNothingIsEvictedOrReleased) {
  SessionRegistry registry(2);
  const std::string id = CreateOne(registry);
  EXPECT_TRUE(registry.EvictIdle(1'000'000).empty());
  registry.ReleaseAll();
  EXPECT_TRUE(registry.Find(id).ok());  // memory is the only copy
}

TEST(SessionRegistry, AnImportedSessionHoldsTheExportedSamples) {
  SessionRegistry registry(4);
  auto original = registry.Create(FeatureSettings(), "config", 0);
  ASSERT_TRUE(original.ok());
  ASSERT_TRUE(
      original->session->AddSamples(Eigen::MatrixXd::Ones(2, kDimension), {1, 0}, "r1", 0).ok());
  const SessionState exported = original->session->ExportState();
  auto imported = registry.Import(FeatureSettings(), "config", exported, 0);
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  EXPECT_NE(imported->session->id(), original->session->id());
  EXPECT_EQ(imported->session->ExportState().features, exported.features);
  EXPECT_TRUE(registry.Find(imported->session->id()).ok());
}

TEST(SessionRegistry, AnImportThatFailsLeavesNoSessionBehind) {
  SessionRegistry registry(4);
  SessionState unlabelled;
  unlabelled.features = Eigen::MatrixXd::Ones(1, kDimension);
  unlabelled.labels = {-1};
  EXPECT_EQ(registry.Import(FeatureSettings(), "config", unlabelled, 0).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_TRUE(registry.Resident().empty());
}

TEST(SessionListing, PagesWalkEverySessionOnceInIdOrder) {
  SessionRegistry registry(8);
  std::vector<std::string> created;
  for (int i = 0; i < 5; ++i) created.push_back(CreateOne(registry));
  std::sort(created.begin(), created.end());
  std::vector<std::string> listed;
  std::string token;
  int pages = 0;
  do {
    auto page = ListSessionPage(registry, token, 2);
    ASSERT_TRUE(page.ok());
    for (const auto& session : page->sessions) listed.push_back(session.id);
    token = page->next_page_token;
    ++pages;
  } while (!token.empty());
  EXPECT_EQ(listed, created);
  EXPECT_EQ(pages, 3);  // 2 + 2 + 1
}

TEST(SessionListing, APageSizeOfZeroIsTheDefault) {
  SessionRegistry registry(8);
  for (int i = 0; i < 3; ++i) CreateOne(registry);
  auto page = ListSessionPage(registry, "", 0);
  ASSERT_TRUE(page.ok());
  EXPECT_EQ(page->sessions.size(), 3u);
  EXPECT_TRUE(page->next_page_token.empty());
}

TEST(SessionListing, PagesOfMoreThanTheMaximumAreInvalid) {
  SessionRegistry registry(8);
  EXPECT_EQ(ListSessionPage(registry, "", kMaxSessionPageSize + 1).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_TRUE(ListSessionPage(registry, "", kMaxSessionPageSize).ok());
}

// The registry over a SQLite file, restoring with a decoder that counts its calls.
class StoredRegistry : public testing::StoreTest {
 protected:
  void SetUp() override {
    StoreTest::SetUp();
    auto opened = SqliteSessionStore::Open(path_);
    ASSERT_TRUE(opened.ok()) << opened.status().message();
    store_ = std::move(opened).value();
    registry_ = std::make_unique<SessionRegistry>(
        8, store_.get(), [this](const SessionRecord& record) -> StatusOr<SessionSettings> {
          ++decoded_;
          EXPECT_EQ(record.config, "config");
          return FeatureSettings();
        });
  }

  void TearDown() override {
    registry_.reset();
    store_.reset();
    StoreTest::TearDown();
  }

  std::unique_ptr<SqliteSessionStore> store_;
  std::unique_ptr<SessionRegistry> registry_;
  int decoded_ = 0;
};

TEST_F(StoredRegistry, AnEvictedSessionComesBackWithItsSamplesOnItsNextCall) {
  const std::string id = CreateOne(*registry_);
  auto session = registry_->Find(id);
  ASSERT_TRUE(session.ok());
  ASSERT_TRUE((*session)->AddSamples(Eigen::MatrixXd::Ones(2, kDimension), {1, 0}, "r1", 10).ok());
  const SessionState before = (*session)->ExportState();
  session->reset();  // no call holds it any more
  EXPECT_EQ(registry_->EvictIdle(20), std::vector<std::string>{id});
  EXPECT_TRUE(registry_->Resident().empty());
  EXPECT_EQ(decoded_, 0);

  auto restored = registry_->Find(id);
  ASSERT_TRUE(restored.ok()) << restored.status().message();
  EXPECT_EQ(decoded_, 1);
  EXPECT_EQ((*restored)->ExportState().features, before.features);
  EXPECT_EQ((*restored)->ExportState().labels, before.labels);
}

TEST_F(StoredRegistry, ASessionInUseOrUsedSinceTheCutoffStaysInMemory) {
  const std::string held = CreateOne(*registry_);
  auto session = registry_->Find(held);
  ASSERT_TRUE(session.ok());
  auto recent = registry_->Create(FeatureSettings(), "config", 100);
  ASSERT_TRUE(recent.ok());
  recent->session.reset();
  EXPECT_TRUE(registry_->EvictIdle(50).empty());
  EXPECT_EQ(registry_->Resident().size(), 2u);
}

TEST_F(StoredRegistry, ASnapshotIsStoredOnceLearningSinceTheLastTookThePolicysTime) {
  // 1 ns: every update takes longer; an hour: none does (no timing is asserted).
  for (const auto budget :
       {std::chrono::nanoseconds(1), std::chrono::nanoseconds(std::chrono::hours(1))}) {
    registry_->set_policy({.snapshot_every = 0, .snapshot_after_learning = budget});
    const std::string id = CreateOne(*registry_);
    auto session = registry_->Find(id);
    ASSERT_TRUE(session.ok());
    ASSERT_TRUE(
        (*session)->AddSamples(Eigen::MatrixXd::Ones(3, kDimension), {1, 0, 1}, "r", 10).ok());
    const auto snapshot = store_->LoadLatestSnapshot(id);
    ASSERT_TRUE(snapshot.ok());
    if (budget == std::chrono::nanoseconds(1)) {
      ASSERT_TRUE(snapshot->has_value());
      EXPECT_EQ((*snapshot)->sample_count, 3);
    } else {
      EXPECT_FALSE(snapshot->has_value());
    }
  }
}

TEST_F(StoredRegistry, ADeletedSessionIsGoneFromTheStoreToo) {
  const std::string id = CreateOne(*registry_);
  ASSERT_TRUE(registry_->Delete(id).ok());
  EXPECT_EQ(registry_->Find(id).status().code(), StatusCode::kNotFound);
  EXPECT_EQ(store_->LoadSession(id).status().code(), StatusCode::kNotFound);
}

// The registry of a server restarted on the same store, whose loads are counted.
class RestartedRegistry {
 public:
  explicit RestartedRegistry(SessionStore& store)
      : registry_(8, &store, [](const SessionRecord&) -> StatusOr<SessionSettings> {
          return FeatureSettings();
        }) {
    registry_.set_loader([this, &store](const std::string& id) {
      ++loads_;
      return LoadStoredSession(store, id, [](const SessionRecord&) -> StatusOr<SessionSettings> {
        return FeatureSettings();
      });
    });
  }
  SessionRegistry& operator*() { return registry_; }
  SessionRegistry* operator->() { return &registry_; }
  int loads() const { return loads_; }

 private:
  SessionRegistry registry_;
  int loads_ = 0;
};

void ExpectSameStats(const SessionStats& listed, const SessionStats& expected) {
  for (int label = 0; label < 2; ++label) {
    EXPECT_EQ(listed.samples[label], expected.samples[label]) << "label " << label;
    EXPECT_EQ(listed.components[label], expected.components[label]) << "label " << label;
  }
  EXPECT_EQ(listed.frames, expected.frames);
  EXPECT_EQ(listed.created_unix_ms, expected.created_unix_ms);
  EXPECT_EQ(listed.last_used_unix_ms, expected.last_used_unix_ms);
}

// Samples that make two components of label 1 (far apart) and one of label 0.
Eigen::MatrixXd SpreadSamples() {
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(6, kDimension);
  x.row(1).setConstant(0.01);
  x.row(2).setConstant(50.0);
  x.row(3).setConstant(50.01);
  x.row(4).setConstant(-3.0);
  x.row(5).setConstant(-3.01);
  return x;
}
const std::vector<int> kSpreadLabels = {1, 1, 1, 1, 0, 0};

TEST_F(StoredRegistry, AStoredSessionIsListedFromItsSummaryWithoutBeingLoaded) {
  const std::string id = CreateOne(*registry_);
  auto session = registry_->Find(id);
  ASSERT_TRUE(session.ok());
  ASSERT_TRUE((*session)->AddSamples(SpreadSamples(), kSpreadLabels, "r1", 10).ok());
  const SessionStats before = (*session)->Stats();
  session->reset();
  registry_->ReleaseAll();  // as a server that stops

  RestartedRegistry restarted(*store_);
  const SessionRegistry::Page page = restarted->List("", 10);
  ASSERT_EQ(page.sessions.size(), 1u);
  EXPECT_EQ(page.sessions[0].id, id);
  EXPECT_EQ(page.sessions[0].settings.feature_dimension, kDimension);
  ExpectSameStats(page.sessions[0].stats, before);
  EXPECT_EQ(before.samples[0], 2u);
  EXPECT_EQ(before.samples[1], 4u);
  EXPECT_EQ(before.last_used_unix_ms, 10);
  EXPECT_EQ(restarted.loads(), 0);
  EXPECT_TRUE(restarted->Resident().empty());
}

TEST_F(StoredRegistry, AnEvictedSessionIsListedWithItsLastCall) {
  const std::string id = CreateOne(*registry_);
  auto session = registry_->Find(id);
  ASSERT_TRUE(session.ok());
  ASSERT_TRUE((*session)->AddSamples(SpreadSamples(), kSpreadLabels, "r1", 10).ok());
  ASSERT_TRUE((*session)->ClassifyFeatures(SpreadSamples(), 30).ok());  // learns nothing
  session->reset();
  ASSERT_EQ(registry_->EvictIdle(40), std::vector<std::string>{id});

  RestartedRegistry restarted(*store_);
  const SessionRegistry::Page page = restarted->List("", 10);
  ASSERT_EQ(page.sessions.size(), 1u);
  EXPECT_EQ(page.sessions[0].stats.last_used_unix_ms, 30);
  EXPECT_EQ(restarted.loads(), 0);
}

TEST_F(StoredRegistry, AnImportedSessionIsListedWithItsSamplesWithoutBeingLoaded) {
  SessionState state;
  state.features = SpreadSamples();
  state.labels = kSpreadLabels;
  auto imported = registry_->Import(FeatureSettings(), "config", state, 5);
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  const SessionStats before = imported->session->Stats();
  imported->session.reset();
  registry_->ReleaseAll();

  RestartedRegistry restarted(*store_);
  const SessionRegistry::Page page = restarted->List("", 10);
  ASSERT_EQ(page.sessions.size(), 1u);
  ExpectSameStats(page.sessions[0].stats, before);
  EXPECT_EQ(restarted.loads(), 0);
}

// A sample stored after the last summary (a crash between the two): the listing loads
// the session once, which records its summary, and reads the summary from then on.
TEST_F(StoredRegistry, ASessionWhoseSummaryMissesASampleIsLoadedOnceToBeListed) {
  const std::string id = CreateOne(*registry_);
  auto session = registry_->Find(id);
  ASSERT_TRUE(session.ok());
  ASSERT_TRUE((*session)->AddSamples(SpreadSamples(), kSpreadLabels, "r1", 10).ok());
  session->reset();
  registry_->ReleaseAll();
  const std::vector<double> late(kDimension, 99.0);
  ASSERT_TRUE(store_->AppendSample(id, "late", late, 1).ok());

  RestartedRegistry restarted(*store_);
  const SessionRegistry::Page first = restarted->List("", 10);
  ASSERT_EQ(first.sessions.size(), 1u);
  EXPECT_EQ(restarted.loads(), 1);
  EXPECT_TRUE(restarted->Resident().empty());  // read for the page, not kept
  const SessionRegistry::Page second = restarted->List("", 10);
  ASSERT_EQ(second.sessions.size(), 1u);
  EXPECT_EQ(restarted.loads(), 1);
  auto loaded = restarted->Find(id);
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ((*loaded)->Stats().samples[1], 5u);
  ExpectSameStats(first.sessions[0].stats, (*loaded)->Stats());
  ExpectSameStats(second.sessions[0].stats, (*loaded)->Stats());
}

// Times are the clock the registry is given (unix ms): sessions created at 0, used at 10.
TEST(SessionExpiry, ASessionIdleSinceBeforeTheCutoffIsDeleted) {
  SessionRegistry registry(4);
  const std::string idle = CreateOne(registry);
  auto used = registry.Create(FeatureSettings(), "config", 100);
  ASSERT_TRUE(used.ok());
  const std::string recent = used->session->id();
  used->session.reset();
  EXPECT_EQ(registry.ExpireIdle(50, 1000), std::vector<std::string>{idle});
  EXPECT_EQ(registry.Find(idle).status().code(), StatusCode::kNotFound);
  EXPECT_TRUE(registry.Find(recent).ok());
}

TEST(SessionExpiry, ASessionACallHoldsIsNotDeleted) {
  SessionRegistry registry(4);
  const std::string id = CreateOne(registry);
  auto held = registry.Find(id);
  ASSERT_TRUE(held.ok());
  EXPECT_TRUE(registry.ExpireIdle(1'000'000, 1'000'000).empty());
  held->reset();
  EXPECT_EQ(registry.ExpireIdle(1'000'000, 1'000'000), std::vector<std::string>{id});
}

TEST_F(StoredRegistry, AnExpiredSessionIsGoneFromTheStoreToo) {
  const std::string id = CreateOne(*registry_);
  EXPECT_EQ(registry_->ExpireIdle(50, 1000), std::vector<std::string>{id});
  EXPECT_EQ(store_->LoadSession(id).status().code(), StatusCode::kNotFound);
  EXPECT_EQ(registry_->Find(id).status().code(), StatusCode::kNotFound);
}

TEST_F(StoredRegistry, AnEvictedSessionExpiresByItsLastCallBeforeTheEviction) {
  const std::string id = CreateOne(*registry_);  // last used at 0
  ASSERT_EQ(registry_->EvictIdle(20), std::vector<std::string>{id});
  EXPECT_TRUE(registry_->ExpireIdle(0, 1000).empty());  // used at 0: not before 0
  EXPECT_EQ(registry_->ExpireIdle(1, 1000), std::vector<std::string>{id});
  EXPECT_EQ(store_->LoadSession(id).status().code(), StatusCode::kNotFound);
}

// After a restart the registry has no last use of a stored session: it counts from the
// first sweep that sees it.
TEST_F(StoredRegistry, AStoredSessionNotYetLoadedExpiresCountingFromTheFirstSweep) {
  const std::string id = CreateOne(*registry_);
  registry_->ReleaseAll();  // as after a restart: in the store, not in memory
  SessionRegistry restarted(8, store_.get(), [](const SessionRecord&) -> StatusOr<SessionSettings> {
    return FeatureSettings();
  });
  EXPECT_TRUE(restarted.ExpireIdle(5000, 5000).empty());  // first seen at 5000
  EXPECT_TRUE(restarted.ExpireIdle(5000, 6000).empty());  // not before 5000
  EXPECT_EQ(restarted.ExpireIdle(5001, 7000), std::vector<std::string>{id});
  EXPECT_EQ(store_->LoadSession(id).status().code(), StatusCode::kNotFound);
}

TEST_F(StoredRegistry, ASettingsDecoderErrorIsTheLookupsError) {
  const std::string id = CreateOne(*registry_);
  registry_->ReleaseAll();
  SessionRegistry failing(8, store_.get(), [](const SessionRecord&) -> StatusOr<SessionSettings> {
    return DataLossError("unreadable");
  });
  EXPECT_EQ(failing.Find(id).status().code(), StatusCode::kDataLoss);
}

}  // namespace
}  // namespace relmap::session
