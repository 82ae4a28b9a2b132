// PostgresSessionStore: the store contract on PostgreSQL, and ownership between
// two store instances on one database, as two servers behind a load balancer
// would use it.
#include "session/store/postgres/postgres_session_store.h"

#include <gtest/gtest.h>
#include <libpq-fe.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "session/postgres_backend.h"
#include "session/store_contract.h"

namespace relmap::session {
namespace {

using testing::MakeRecord;
using testing::Numbered;
using testing::SessionStoreDurability;
using testing::SessionStoreSamples;
using testing::SessionStoreSessions;
using testing::SessionStoreSnapshotRoundTrip;
using testing::SessionStoreSnapshots;
using testing::SharedPostgres;

RELMAP_INSTANTIATE_STORE_CONTRACT(Contract, testing::PostgresKind());

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Two or more store instances ("servers") on one fresh schema.
class PostgresOwnership : public ::testing::Test {
 protected:
  void SetUp() override {
    auto scratch = testing::NewPostgresScratch();
    ASSERT_TRUE(scratch.has_value());
    uri_ = scratch->uri;
    scratch_ = *scratch;
  }

  std::unique_ptr<PostgresSessionStore> OpenServer(const PostgresStoreOptions& options = {}) {
    auto store = PostgresSessionStore::Open(uri_, options);
    EXPECT_TRUE(store.ok()) << store.status().message();
    return store.ok() ? std::move(store).value() : nullptr;
  }

  // What kill -9 of the server does to its side of the database: its
  // connections end. pg_terminate_backend with a timeout waits until they have.
  void DropConnectionsOf(const PostgresSessionStore& store) {
    const Status status =
        SharedPostgres()->Execute("postgres",
                                  "SELECT pg_terminate_backend(pid, 10000) FROM pg_stat_activity"
                                  " WHERE application_name = '" +
                                      store.owner_id() + "'");
    ASSERT_TRUE(status.ok()) << status.message();
  }

  // The owner of session `id` as the database has it ("" for none).
  std::string StoredOwner(const std::string& id) {
    auto owner = SharedPostgres()->Query(
        scratch_.database,
        "SELECT owner FROM " + scratch_.schema + ".session_owners WHERE session_id = '" + id + "'");
    EXPECT_TRUE(owner.ok()) << owner.status().message();
    return owner.ok() ? *owner : "?";
  }

  testing::PostgresScratch scratch_;
  std::string uri_;  // a schema of its own
  const std::vector<double> x_ = {0.25, -0.0, 1e-310};
};

TEST_F(PostgresOwnership, CreatorHoldsTheSessionThroughout) {
  auto a = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  auto held = a->AcquireOwnership("s");
  ASSERT_TRUE(held.ok()) << held.status().message();
  EXPECT_TRUE(held->held_throughout);
}

TEST_F(PostgresOwnership, SecondServerIsUnavailableWhileTheFirstIsConnected) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  const Status refused = b->AcquireOwnership("s").status();
  EXPECT_EQ(refused.code(), StatusCode::kUnavailable);
  EXPECT_TRUE(Contains(refused.message(), "owned by server \"" + a->owner_id() + "\""))
      << refused.message();
  EXPECT_TRUE(Contains(refused.message(), "lease until 20")) << refused.message();
  EXPECT_EQ(refused.reason(), ErrorReason::kSessionOwnedElsewhere);
  EXPECT_EQ(refused.metadata().at("sessionId"), "s");
  EXPECT_EQ(refused.metadata().at("owner"), a->owner_id());
  EXPECT_TRUE(refused.metadata().at("leaseExpiresAt").starts_with("20")) << refused.message();
  // Refusing took nothing: the first still holds it.
  EXPECT_TRUE(a->AcquireOwnership("s")->held_throughout);
  EXPECT_TRUE(a->AppendSample("s", "r1", x_, 1).ok());
}

TEST_F(PostgresOwnership, UnknownSessionIsNotFound) {
  auto a = OpenServer();
  EXPECT_EQ(a->AcquireOwnership("ghost").status().code(), StatusCode::kNotFound);
}

TEST_F(PostgresOwnership, DestroyedServerHandsItsSessionsOverAtOnce) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  EXPECT_EQ(StoredOwner("s"), a->owner_id());
  a.reset();
  // Released by the destructor, not left for PostgreSQL to notice the closed
  // connections.
  EXPECT_EQ(StoredOwner("s"), "");
  auto taken = b->AcquireOwnership("s");
  ASSERT_TRUE(taken.ok()) << taken.status().message();
  EXPECT_FALSE(taken->held_throughout);
}

TEST_F(PostgresOwnership, ServerWhoseConnectionsDiedIsTakenOverAtOnce) {
  auto a = OpenServer();  // the default 30 s lease: only the dead connection lets b in
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  DropConnectionsOf(*a);
  auto taken = b->AcquireOwnership("s");
  ASSERT_TRUE(taken.ok()) << taken.status().message();
  EXPECT_FALSE(taken->held_throughout);
}

TEST_F(PostgresOwnership, KilledServerProcessIsTakenOverWellBeforeItsLeaseEnds) {
  auto b = OpenServer();
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(ready[0]);
    auto a = PostgresSessionStore::Open(uri_);
    if (!a.ok() || !(*a)->CreateSession(MakeRecord("s")).ok()) _exit(2);
    const char byte = 1;
    if (write(ready[1], &byte, 1) != 1) _exit(3);
    pause();  // until killed, holding the session
    _exit(4);
  }
  close(ready[1]);
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1) << "the first server did not start";
  close(ready[0]);
  EXPECT_EQ(b->AcquireOwnership("s").status().code(), StatusCode::kUnavailable);

  const auto killed = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int wait_status = 0;
  ASSERT_EQ(waitpid(child, &wait_status, 0), child);
  // PostgreSQL sees the closed socket at once, yet ends the backend a moment
  // later: retry for a while, far less than the 30 s lease.
  StatusOr<SessionStore::Ownership> taken = Status(StatusCode::kUnavailable, "not tried");
  while (std::chrono::steady_clock::now() - killed < std::chrono::seconds(5)) {
    taken = b->AcquireOwnership("s");
    if (taken.ok()) break;
    ASSERT_EQ(taken.status().code(), StatusCode::kUnavailable) << taken.status().message();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(taken.ok()) << taken.status().message();
  EXPECT_FALSE(taken->held_throughout);
  RecordProperty("takeover_ms",
                 static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                      std::chrono::steady_clock::now() - killed)
                                      .count()));
}

TEST_F(PostgresOwnership, WritesOfTheFormerOwnerAreAbortedAndStoreNothing) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s", 2)).ok());
  auto model = cmm::CollaborativeMixtureModels::Create(cmm::CmmConfig{}, 2).value();
  DropConnectionsOf(*a);
  ASSERT_TRUE(b->AcquireOwnership("s").ok());

  // a's pool reconnects its dropped connection and finds the session gone to b.
  const std::vector<double> x = {1.0, 2.0};
  const Status append = a->AppendSample("s", "r1", x, 1).status();
  EXPECT_EQ(append.code(), StatusCode::kAborted);
  EXPECT_TRUE(Contains(append.message(), "taken over by server \"" + b->owner_id() + "\""))
      << append.message();
  EXPECT_EQ(a->SaveSnapshot("s", model.Snapshot(), 0).code(), StatusCode::kAborted);
  EXPECT_EQ(a->IncrementCounters("s", {.frames_computed = 1, .interactions = 1}).code(),
            StatusCode::kAborted);

  EXPECT_TRUE(b->LoadSamples("s")->empty());
  EXPECT_FALSE(b->LoadLatestSnapshot("s")->has_value());
  EXPECT_EQ(b->LoadSession("s")->counters.frames_computed, 0);
  // The new owner's history goes on from where the store stands, not forked.
  EXPECT_EQ(*b->AppendSample("s", "r1", x, 0), 0);
  // And a cannot take it back while b is connected.
  EXPECT_EQ(a->AcquireOwnership("s").status().code(), StatusCode::kUnavailable);
}

TEST_F(PostgresOwnership, WriteWithoutOwningTheSessionIsAborted) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  const Status status = b->AppendSample("s", "r1", x_, 1).status();
  EXPECT_EQ(status.code(), StatusCode::kAborted);
  EXPECT_TRUE(Contains(status.message(), "not owned by this server")) << status.message();
  EXPECT_TRUE(a->LoadSamples("s")->empty());
}

TEST_F(PostgresOwnership, ReleaseAllowsAnImmediateTakeover) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  a->ReleaseOwnership("s");
  auto taken = b->AcquireOwnership("s");
  ASSERT_TRUE(taken.ok()) << taken.status().message();
  EXPECT_FALSE(taken->held_throughout);
  EXPECT_EQ(a->AcquireOwnership("s").status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(a->AppendSample("s", "r1", x_, 1).status().code(), StatusCode::kAborted);
}

TEST_F(PostgresOwnership, ReacquiringAfterAnotherServerHeldItIsNotHeldThroughout) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  a->ReleaseOwnership("s");
  ASSERT_TRUE(b->AcquireOwnership("s").ok());
  ASSERT_TRUE(b->AppendSample("s", "r1", x_, 1).ok());
  b->ReleaseOwnership("s");
  auto back = a->AcquireOwnership("s");
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_FALSE(back->held_throughout);  // a's copy lacks b's sample
  EXPECT_EQ(*a->AppendSample("s", "r2", x_, 0), 1);
}

TEST_F(PostgresOwnership, ExpiredLeaseLetsAnotherServerTakeOver) {
  PostgresStoreOptions short_lease;
  short_lease.lease_ttl = std::chrono::milliseconds(1000);
  auto a = OpenServer(short_lease);
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  EXPECT_EQ(b->AcquireOwnership("s").status().code(), StatusCode::kUnavailable);
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  auto taken = b->AcquireOwnership("s");  // a is still connected: only the lease ran out
  ASSERT_TRUE(taken.ok()) << taken.status().message();
  EXPECT_FALSE(taken->held_throughout);
  EXPECT_EQ(a->AppendSample("s", "r1", x_, 1).status().code(), StatusCode::kAborted);
}

TEST_F(PostgresOwnership, WritesRenewTheLease) {
  PostgresStoreOptions lease;
  lease.lease_ttl = std::chrono::milliseconds(1500);
  auto a = OpenServer(lease);
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  ASSERT_TRUE(a->AppendSample("s", "r1", x_, 1).ok());  // renews until t = 2.5 s
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  // t = 2 s: past the first lease, within the renewed one.
  EXPECT_EQ(b->AcquireOwnership("s").status().code(), StatusCode::kUnavailable);
}

TEST_F(PostgresOwnership, AcknowledgedSampleIsLoadedBitForBitByTheOtherServer) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  ASSERT_EQ(*a->AppendSample("s", "r1", x_, 1), 0);
  auto samples = b->LoadSamples("s");  // any server reads; no ownership needed
  ASSERT_TRUE(samples.ok()) << samples.status().message();
  ASSERT_EQ(samples->size(), 1u);
  for (std::size_t k = 0; k < x_.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>((*samples)[0].features[k]),
              std::bit_cast<std::uint64_t>(x_[k]));
  }
}

TEST_F(PostgresOwnership, ConcurrentAcquisitionsHaveOneWinner) {
  constexpr int kServers = 4;
  std::vector<std::unique_ptr<PostgresSessionStore>> servers;
  for (int i = 0; i < kServers; ++i) servers.push_back(OpenServer());
  ASSERT_TRUE(servers[0]->CreateSession(MakeRecord("s")).ok());
  servers[0]->ReleaseOwnership("s");
  std::vector<StatusCode> codes(kServers);
  std::vector<std::thread> threads;
  for (int i = 0; i < kServers; ++i) {
    threads.emplace_back([&, i] { codes[i] = servers[i]->AcquireOwnership("s").status().code(); });
  }
  for (std::thread& thread : threads) thread.join();
  int winners = 0;
  for (StatusCode code : codes) {
    if (code == StatusCode::kOk) {
      ++winners;
    } else {
      EXPECT_EQ(code, StatusCode::kUnavailable);
    }
  }
  EXPECT_EQ(winners, 1);
}

TEST_F(PostgresOwnership, DeletedByAnotherServerIsNotFoundForTheOwner) {
  auto a = OpenServer();
  auto b = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  ASSERT_TRUE(b->DeleteSession("s").ok());
  EXPECT_EQ(a->AppendSample("s", "r1", x_, 1).status().code(), StatusCode::kNotFound);
  EXPECT_EQ(a->AcquireOwnership("s").status().code(), StatusCode::kNotFound);
}

TEST_F(PostgresOwnership, OwnerRowLockedByAStuckTransactionIsUnavailableAfterTheLockTimeout) {
  PostgresStoreOptions impatient;
  impatient.lock_timeout = std::chrono::milliseconds(200);
  auto a = OpenServer(impatient);
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  // A server that stopped mid-transaction while holding the row.
  PGconn* stuck = PQconnectdb(uri_.c_str());
  ASSERT_EQ(PQstatus(stuck), CONNECTION_OK) << PQerrorMessage(stuck);
  PQclear(PQexec(stuck, "BEGIN"));
  PGresult* locked = PQexec(stuck, "SELECT 1 FROM session_owners FOR UPDATE");
  EXPECT_EQ(PQresultStatus(locked), PGRES_TUPLES_OK) << PQerrorMessage(stuck);
  PQclear(locked);

  const auto start = std::chrono::steady_clock::now();
  const Status status = a->AcquireOwnership("s").status();
  const auto waited = std::chrono::steady_clock::now() - start;
  EXPECT_EQ(status.code(), StatusCode::kUnavailable) << status.message();
  EXPECT_TRUE(Contains(status.message(), "lock timeout")) << status.message();
  EXPECT_LT(waited, std::chrono::seconds(5));
  PQfinish(stuck);  // its transaction ends with its connection
  EXPECT_TRUE(a->AcquireOwnership("s").ok());
}

using PostgresConnections = PostgresOwnership;

// PostgreSQL's text holds UTF-8 without NUL bytes; SQLite's TEXT takes any
// bytes. The service's ids are UTF-8 (protobuf strings) but may hold a NUL.
TEST_F(PostgresConnections, TextPostgresCannotHoldIsAnInvalidArgument) {
  auto a = OpenServer();
  EXPECT_EQ(a->CreateSession(MakeRecord("bad\xff")).code(), StatusCode::kInvalidArgument);
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  const Status nul = a->AppendSample("s", std::string("r\0", 2), x_, 1).status();
  EXPECT_EQ(nul.code(), StatusCode::kInvalidArgument) << nul.message();
  EXPECT_TRUE(a->LoadSamples("s")->empty());
  // The store is still usable afterwards: the failed transaction was rolled back.
  EXPECT_EQ(*a->AppendSample("s", "r1", x_, 1), 0);
}

TEST_F(PostgresConnections, DroppedConnectionIsReconnectedOnTheNextCall) {
  auto a = OpenServer();
  ASSERT_TRUE(a->CreateSession(MakeRecord("s")).ok());
  DropConnectionsOf(*a);
  // A read finds its connection dead, reconnects and runs again.
  auto loaded = a->LoadSession("s");
  EXPECT_TRUE(loaded.ok()) << loaded.status().message();
  // A transaction finds it dead at BEGIN, reconnects and goes on: a's session
  // is still its own (its lease runs, nobody took it).
  DropConnectionsOf(*a);
  auto held = a->AcquireOwnership("s");
  ASSERT_TRUE(held.ok()) << held.status().message();
  EXPECT_TRUE(held->held_throughout);
  EXPECT_TRUE(a->AppendSample("s", "r1", x_, 1).ok());
}

TEST_F(PostgresConnections, UnreachableServerIsUnavailable) {
  PostgresStoreOptions options;
  options.connect_timeout = std::chrono::seconds(2);
  // Port 1 on loopback: nothing listens there.
  auto store = PostgresSessionStore::Open("postgresql://postgres@127.0.0.1:1/none", options);
  ASSERT_FALSE(store.ok());
  EXPECT_EQ(store.status().code(), StatusCode::kUnavailable);
  EXPECT_TRUE(Contains(store.status().message(), "cannot connect")) << store.status().message();
}

TEST_F(PostgresConnections, ServersOpeningAFreshDatabaseTogetherAllMigrateIt) {
  constexpr int kServers = 4;
  std::vector<Status> opened(kServers);
  std::vector<std::thread> threads;
  for (int i = 0; i < kServers; ++i) {
    threads.emplace_back([&, i] { opened[i] = PostgresSessionStore::Open(uri_).status(); });
  }
  for (std::thread& thread : threads) thread.join();
  for (const Status& status : opened) EXPECT_TRUE(status.ok()) << status.message();
}

TEST_F(PostgresConnections, BadOptionsAreInvalidArguments) {
  PostgresStoreOptions long_id;
  long_id.owner_id = std::string(64, 'x');  // application_name keeps 63 bytes
  EXPECT_EQ(PostgresSessionStore::Open(uri_, long_id).status().code(),
            StatusCode::kInvalidArgument);
  PostgresStoreOptions no_connections;
  no_connections.max_connections = 0;
  EXPECT_EQ(PostgresSessionStore::Open(uri_, no_connections).status().code(),
            StatusCode::kInvalidArgument);
}

TEST_F(PostgresConnections, GeneratedOwnerIdsAreDistinctApplicationNames) {
  auto a = OpenServer();
  auto b = OpenServer();
  EXPECT_NE(a->owner_id(), b->owner_id());
  EXPECT_TRUE(a->owner_id().starts_with("relmap-")) << a->owner_id();
  EXPECT_LE(a->owner_id().size(), 63u);
}

}  // namespace
}  // namespace relmap::session
