// Durability end to end: after `kill -9` and a restart on the same data
// directory, every session and acknowledged sample is back and the model
// predicts exactly as before.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "integration/server_process.h"
#include "relmap/v1/relevance_service.grpc.pb.h"
#include "session/store/sqlite/sqlite_session_store.h"

namespace relmap {
namespace {

using v1::RelevanceService;

void Authorise(grpc::ClientContext& context, const std::string& token) {
  context.AddMetadata("authorization", "Bearer " + token);
}

v1::AddSamplesRequest Samples(const std::string& id, const std::string& request_id) {
  v1::AddSamplesRequest request;
  request.set_session_id(id);
  request.set_request_id(request_id);
  for (int i = 0; i < 60; ++i) {
    v1::LabelledFeature* sample = request.add_samples();
    const bool moveable = i % 3 == 0;
    sample->mutable_feature()->add_values((moveable ? 0.0 : 1.0) + 0.01 * (i % 7));
    sample->mutable_feature()->add_values(0.02 * (i % 5));
    sample->set_label(moveable ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
  }
  return request;
}

v1::ClassifyFeaturesResponse Classify(RelevanceService::Stub& stub, const std::string& id,
                                      const std::string& token) {
  grpc::ClientContext context;
  Authorise(context, token);
  v1::ClassifyFeaturesRequest request;
  request.set_session_id(id);
  for (int i = 0; i < 21; ++i) {
    v1::FeatureVector* vector = request.add_features();
    vector->add_values(-0.2 + 0.07 * i);
    vector->add_values(0.04);
  }
  v1::ClassifyFeaturesResponse response;
  EXPECT_TRUE(stub.ClassifyFeatures(&context, request, &response).ok());
  return response;
}

// A new 2-d session (seed `seed`) that has learned the 60 samples of Samples().
struct TrainedSession {
  std::string id;
  std::string token;
  v1::AddSamplesResponse added;
};

TrainedSession CreateTrainedSession(RelevanceService::Stub& stub, std::uint64_t seed) {
  grpc::ClientContext create_context;
  v1::CreateSessionRequest create;
  create.mutable_config()->set_feature_dimension(2);
  create.mutable_config()->set_seed(seed);
  v1::CreateSessionResponse created;
  EXPECT_TRUE(stub.CreateSession(&create_context, create, &created).ok());
  TrainedSession trained{created.session_id(), created.session_token(), {}};
  grpc::ClientContext add_context;
  Authorise(add_context, trained.token);
  EXPECT_TRUE(stub.AddSamples(&add_context, Samples(trained.id, "batch-1"), &trained.added).ok());
  EXPECT_EQ(trained.added.stats().moveable_samples() + trained.added.stats().non_moveable_samples(),
            60u);
  return trained;
}

// A 2-d session with the 60 samples of Samples(), on a server started with
// `arguments`; its predictions; then the server is killed with SIGKILL.
struct KilledSession {
  std::string id;
  std::string token;
  v1::ClassifyFeaturesResponse predictions;
};

KilledSession TrainThenKill(std::vector<std::string> arguments) {
  testing::ServerProcess server(std::move(arguments));
  auto stub = RelevanceService::NewStub(server.Channel());
  const TrainedSession trained = CreateTrainedSession(*stub, 17);
  KilledSession killed{trained.id, trained.token, Classify(*stub, trained.id, trained.token)};
  server.Kill();
  return killed;
}

TEST(Persistence, AcknowledgedSamplesSurviveKillMinusNine) {
  const std::string dir =
      ::testing::TempDir() + "/relmap_persistence_" + std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  const KilledSession killed = TrainThenKill({"--data-dir", dir});
  const std::string& id = killed.id;
  const std::string& token = killed.token;
  const v1::ClassifyFeaturesResponse& before = killed.predictions;

  testing::ServerProcess restarted({"--data-dir", dir});
  auto stub = RelevanceService::NewStub(restarted.Channel());
  grpc::ClientContext get_context;
  Authorise(get_context, token);
  v1::GetSessionRequest get;
  get.set_session_id(id);
  v1::GetSessionResponse session;
  ASSERT_TRUE(stub->GetSession(&get_context, get, &session).ok());
  EXPECT_EQ(session.stats().moveable_samples(), 20u);
  EXPECT_EQ(session.stats().non_moveable_samples(), 40u);
  EXPECT_EQ(session.config().seed(), 17u);

  const v1::ClassifyFeaturesResponse after = Classify(*stub, id, token);
  ASSERT_EQ(after.relevance_size(), before.relevance_size());
  for (int i = 0; i < after.relevance_size(); ++i) {
    EXPECT_EQ(after.relevance(i), before.relevance(i)) << "vector " << i;  // bit for bit
  }

  // The same batch posted again after the restart is not learned twice.
  grpc::ClientContext retry_context;
  Authorise(retry_context, token);
  v1::AddSamplesResponse retried;
  ASSERT_TRUE(stub->AddSamples(&retry_context, Samples(id, "batch-1"), &retried).ok());
  EXPECT_EQ(retried.stats().moveable_samples() + retried.stats().non_moveable_samples(), 60u);
  std::filesystem::remove_all(dir);
}

TEST(Persistence, RestartFromASnapshotPredictsLikeAFullReplay) {
  const std::string dir = ::testing::TempDir() + "/relmap_snapshots_" + std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  // Snapshots by count only: none after some time of learning, whatever the machine's speed.
  const KilledSession killed = TrainThenKill(
      {"--data-dir", dir, "--snapshot-every", "25", "--snapshot-after-learning-ms", "0"});
  const std::string& id = killed.id;
  const std::string& token = killed.token;
  const v1::ClassifyFeaturesResponse& before = killed.predictions;
  {
    // Snapshots after 25 and 50 of the 60 samples; the latest is kept.
    auto store = session::SqliteSessionStore::Open(dir + "/relmap.sqlite");
    ASSERT_TRUE(store.ok()) << store.status().message();
    auto snapshot = (*store)->LoadLatestSnapshot(id);
    ASSERT_TRUE(snapshot.ok() && snapshot->has_value());
    EXPECT_EQ((*snapshot)->sample_count, 50);
  }
  testing::ServerProcess restarted({"--data-dir", dir});
  auto stub = RelevanceService::NewStub(restarted.Channel());
  const v1::ClassifyFeaturesResponse after = Classify(*stub, id, token);
  ASSERT_EQ(after.relevance_size(), before.relevance_size());
  for (int i = 0; i < after.relevance_size(); ++i)
    EXPECT_EQ(after.relevance(i), before.relevance(i));
  std::filesystem::remove_all(dir);
}

TEST(Persistence, IdleSessionsLeaveMemoryAndComeBackOnTheirNextCall) {
  const std::string dir = ::testing::TempDir() + "/relmap_eviction_" + std::to_string(::getpid());
  const std::string metrics_port_file = dir + "-metrics-port";
  std::filesystem::remove_all(dir);
  testing::ServerProcess server({"--data-dir", dir, "--evict-idle-seconds", "1", "--metrics-listen",
                                 "127.0.0.1:0", "--metrics-port-file", metrics_port_file});
  auto stub = RelevanceService::NewStub(server.Channel());
  const TrainedSession created = CreateTrainedSession(*stub, 0);
  const auto before = Classify(*stub, created.id, created.token);
  int metrics_port = 0;
  std::ifstream(metrics_port_file) >> metrics_port;
  EXPECT_NE(testing::HttpGet(metrics_port, "/metrics").find("relmap_sessions 1"),
            std::string::npos);

  // Idle for over a second: evicted within the next check (every second).
  std::this_thread::sleep_for(std::chrono::milliseconds(2600));
  EXPECT_NE(testing::HttpGet(metrics_port, "/metrics").find("relmap_sessions 0"),
            std::string::npos);

  const auto after = Classify(*stub, created.id, created.token);
  ASSERT_EQ(after.relevance_size(), before.relevance_size());
  for (int i = 0; i < after.relevance_size(); ++i)
    EXPECT_EQ(after.relevance(i), before.relevance(i));
  EXPECT_NE(testing::HttpGet(metrics_port, "/metrics").find("relmap_sessions 1"),
            std::string::npos);
  std::filesystem::remove_all(dir);
  std::remove(metrics_port_file.c_str());
}

grpc::StatusCode GetSessionCode(RelevanceService::Stub& stub, const TrainedSession& session) {
  grpc::ClientContext context;
  Authorise(context, session.token);
  v1::GetSessionRequest request;
  request.set_session_id(session.id);
  v1::GetSessionResponse response;
  return stub.GetSession(&context, request, &response).error_code();
}

TEST(Persistence, SessionsIdleLongerThanTheExpiryAreDeletedFromMemoryAndStore) {
  const std::string dir = ::testing::TempDir() + "/relmap_expiry_" + std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  {
    testing::ServerProcess server({"--data-dir", dir, "--session-idle-expiry-seconds", "2"});
    auto stub = RelevanceService::NewStub(server.Channel());
    const TrainedSession idle = CreateTrainedSession(*stub, 0);
    const TrainedSession busy = CreateTrainedSession(*stub, 1);
    // The busy session is used every 0.5 s (its lastUsedUnixMs), the idle one not at all,
    // for 4 s: past the 2 s expiry and its check every second.
    for (int i = 0; i < 8; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
      EXPECT_EQ(Classify(*stub, busy.id, busy.token).relevance_size(), 21) << i;
    }
    EXPECT_EQ(GetSessionCode(*stub, busy), grpc::StatusCode::OK);
    EXPECT_EQ(GetSessionCode(*stub, idle), grpc::StatusCode::NOT_FOUND);
    EXPECT_EQ(server.Stop(), 0);
  }
  auto opened = session::SqliteSessionStore::Open(dir + "/relmap.sqlite");
  ASSERT_TRUE(opened.ok()) << opened.status().message();
  auto stored = (*opened)->ListSessions();
  ASSERT_TRUE(stored.ok());
  EXPECT_EQ(stored->size(), 1u);  // the busy one
  std::filesystem::remove_all(dir);
}

v1::GetSessionResponse GetSession(RelevanceService::Stub& stub, const std::string& id,
                                  const std::string& token) {
  grpc::ClientContext context;
  Authorise(context, token);
  v1::GetSessionRequest request;
  request.set_session_id(id);
  v1::GetSessionResponse response;
  EXPECT_TRUE(stub.GetSession(&context, request, &response).ok());
  return response;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// After a restart, ListSessions answers from the summaries the store keeps: every
// session as GetSession showed it before the restart, and none loaded for it (the
// server logs each load of a stored session, "restored session=<id>").
TEST(Persistence, ListingAfterARestartShowsStoredSessionsWithoutLoadingThem) {
  const std::string dir = ::testing::TempDir() + "/relmap_listing_" + std::to_string(::getpid());
  const std::string log = dir + "-server.log";
  std::filesystem::remove_all(dir);
  std::remove(log.c_str());
  std::map<std::string, v1::GetSessionResponse> before;
  std::map<std::string, std::string> tokens;
  {
    testing::ServerProcess server({"--data-dir", dir});
    auto stub = RelevanceService::NewStub(server.Channel());
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
      const TrainedSession trained = CreateTrainedSession(*stub, seed);
      Classify(*stub, trained.id, trained.token);  // a last call that learns nothing
      tokens[trained.id] = trained.token;
    }
    grpc::ClientContext context;
    v1::CreateSessionRequest create;
    create.mutable_config()->set_feature_dimension(2);
    v1::CreateSessionResponse empty;
    ASSERT_TRUE(stub->CreateSession(&context, create, &empty).ok());
    tokens[empty.session_id()] = empty.session_token();
    for (const auto& [id, token] : tokens) before[id] = GetSession(*stub, id, token);
    EXPECT_EQ(server.Stop(), 0);
  }

  testing::ServerProcess server({"--data-dir", dir}, log);
  auto stub = RelevanceService::NewStub(server.Channel());
  grpc::ClientContext context;
  v1::ListSessionsRequest request;
  request.set_page_size(1000);
  v1::ListSessionsResponse listed;
  ASSERT_TRUE(stub->ListSessions(&context, request, &listed).ok());
  ASSERT_EQ(listed.sessions_size(), 4);
  for (const v1::GetSessionResponse& session : listed.sessions()) {
    const auto it = before.find(session.session_id());
    ASSERT_NE(it, before.end()) << session.session_id();
    EXPECT_EQ(session.stats().SerializeAsString(), it->second.stats().SerializeAsString())
        << session.stats().DebugString() << " listed; before the restart "
        << it->second.stats().DebugString();
    EXPECT_EQ(session.config().SerializeAsString(), it->second.config().SerializeAsString());
  }
  EXPECT_EQ(ReadFile(log).find("restored session="), std::string::npos) << ReadFile(log);

  // A call loads the session, and the log says so.
  const std::string& id = listed.sessions(1).session_id();
  const v1::GetSessionResponse loaded = GetSession(*stub, id, tokens[id]);
  EXPECT_EQ(loaded.stats().SerializeAsString(), listed.sessions(1).stats().SerializeAsString());
  EXPECT_NE(ReadFile(log).find("restored session=" + id), std::string::npos) << ReadFile(log);
  EXPECT_EQ(server.Stop(), 0);
  std::filesystem::remove_all(dir);
  std::remove(log.c_str());
}

// The summary is recorded by every call that learns, not only at shutdown: after
// `kill -9`, ListSessions still shows a session as it was, without loading it.
TEST(Persistence, ListingAfterKillMinusNineShowsTheLastLearningCallWithoutLoading) {
  const std::string dir =
      ::testing::TempDir() + "/relmap_listing_kill_" + std::to_string(::getpid());
  const std::string log = dir + "-server.log";
  std::filesystem::remove_all(dir);
  std::remove(log.c_str());
  v1::GetSessionResponse before;
  {
    testing::ServerProcess server({"--data-dir", dir});
    auto stub = RelevanceService::NewStub(server.Channel());
    const TrainedSession trained = CreateTrainedSession(*stub, 3);
    before = GetSession(*stub, trained.id, trained.token);
    server.Kill();
  }
  testing::ServerProcess server({"--data-dir", dir}, log);
  auto stub = RelevanceService::NewStub(server.Channel());
  grpc::ClientContext context;
  v1::ListSessionsResponse listed;
  ASSERT_TRUE(stub->ListSessions(&context, {}, &listed).ok());
  ASSERT_EQ(listed.sessions_size(), 1);
  EXPECT_EQ(listed.sessions(0).stats().SerializeAsString(), before.stats().SerializeAsString())
      << listed.sessions(0).stats().DebugString() << " listed; before the kill "
      << before.stats().DebugString();
  EXPECT_EQ(ReadFile(log).find("restored session="), std::string::npos) << ReadFile(log);
  EXPECT_EQ(server.Stop(), 0);
  std::filesystem::remove_all(dir);
  std::remove(log.c_str());
}

TEST(ExportImport, AnImportedSessionPredictsBitForBitLikeTheOriginal) {
  testing::ServerProcess server;
  auto stub = RelevanceService::NewStub(server.Channel());
  const TrainedSession created = CreateTrainedSession(*stub, 5);
  const v1::AddSamplesResponse& added = created.added;

  grpc::ClientContext export_context;
  Authorise(export_context, created.token);
  v1::ExportSessionRequest export_request;
  export_request.set_session_id(created.id);
  v1::ExportSessionResponse exported;
  ASSERT_TRUE(stub->ExportSession(&export_context, export_request, &exported).ok());
  EXPECT_EQ(exported.state().samples_size(), 60);
  EXPECT_EQ(exported.state().config().seed(), 5u);

  grpc::ClientContext import_context;
  v1::ImportSessionRequest import_request;
  *import_request.mutable_state() = exported.state();
  v1::ImportSessionResponse imported;
  ASSERT_TRUE(stub->ImportSession(&import_context, import_request, &imported).ok());
  EXPECT_NE(imported.session_id(), created.id);
  EXPECT_EQ(imported.stats().moveable_samples(), added.stats().moveable_samples());
  EXPECT_EQ(imported.stats().moveable_components(), added.stats().moveable_components());

  const auto original = Classify(*stub, created.id, created.token);
  const auto copy = Classify(*stub, imported.session_id(), imported.session_token());
  ASSERT_EQ(original.relevance_size(), copy.relevance_size());
  for (int i = 0; i < copy.relevance_size(); ++i)
    EXPECT_EQ(copy.relevance(i), original.relevance(i));

  grpc::ClientContext bad_context;
  import_request.mutable_state()->clear_target_rng_state();
  EXPECT_EQ(stub->ImportSession(&bad_context, import_request, &imported).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
}

}  // namespace
}  // namespace relmap
