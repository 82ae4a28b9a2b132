// Two relmap-servers sharing one PostgreSQL behind nginx (deploy/nginx), all real
// processes on loopback: sessions stay on one server, a server killed with SIGKILL
// loses no acknowledged sample (the other takes its sessions over), and when it
// comes back the cluster goes on; either server lists every session.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cluster/nginx_process.h"
#include "integration/test_support.h"
#include "local_server.h"
#include "relevance_client.h"
#include "support/postgres_instance.h"

namespace relmap::testing {
namespace {

constexpr int kSessions = 6;

// Lines of `path` that mention `session_id` in a call other than CreateSession (which
// carries no session header and may land on any server).
int SessionCallsIn(const std::string& path, const std::string& session_id) {
  std::ifstream in(path);
  int calls = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find("session=" + session_id) != std::string::npos &&
        line.find("rpc=") != std::string::npos &&
        line.find("rpc=CreateSession") == std::string::npos) {
      ++calls;
    }
  }
  return calls;
}

// One server of the cluster, on a fixed port so that nginx's ring keeps it across a
// restart; its log in `log_path`, appended to across restarts.
class ClusterServer {
 public:
  ClusterServer(std::string store_uri, int port, std::string log_path)
      : store_uri_(std::move(store_uri)), port_(port), log_path_(std::move(log_path)) {}

  void Start() {
    client::LocalServerOptions options;
    options.memory_only = true;  // the store is PostgreSQL
    // A short lease, so that a session handed back to a restarted server is free
    // 2 s after its last call on the other one, well within the client's deadline.
    options.extra_arguments = {"--store",         store_uri_, "--listen",      Address(),
                               "--lease-seconds", "2",        "--max-threads", "8"};
    options.log_path = log_path_ + "." + std::to_string(starts_++);
    auto started = client::LocalServer::Start(RELMAP_SERVER_BINARY, options);
    ASSERT_TRUE(started.ok()) << started.status().message();
    process_ = std::move(started).value();
  }
  void Kill() {
    ASSERT_NE(process_, nullptr);
    ::kill(process_->pid(), SIGKILL);
    process_.reset();  // reaps it
  }
  std::string Address() const { return "127.0.0.1:" + std::to_string(port_); }
  // Calls on `session_id` in every log this server has written.
  int CallsOn(const std::string& session_id) const {
    int calls = 0;
    for (int i = 0; i < starts_; ++i) {
      calls += SessionCallsIn(log_path_ + "." + std::to_string(i), session_id);
    }
    return calls;
  }
  bool Logged(const std::string& text) const { return LinesLogging(text) > 0; }
  // Lines of every log this server has written that contain `text`.
  int LinesLogging(const std::string& text) const {
    int lines = 0;
    for (int i = 0; i < starts_; ++i) {
      std::ifstream in(log_path_ + "." + std::to_string(i));
      for (std::string line; std::getline(in, line);) lines += line.find(text) != std::string::npos;
    }
    return lines;
  }

 private:
  std::string store_uri_;
  int port_;
  std::string log_path_;
  int starts_ = 0;
  std::unique_ptr<client::LocalServer> process_;
};

struct ExploredSession {
  client::SessionHandle handle;
  int acknowledged = 0;  // outcomes the cluster acknowledged
  int frames_lost = 0;   // outcomes refused because the session moved after its maps
};

class Cluster : public ::testing::Test {
 protected:
  void SetUp() override {
    auto postgres = PostgresInstance::Start();
    ASSERT_TRUE(postgres.ok()) << postgres.status().message();
    postgres_ = std::move(postgres).value();
    ASSERT_TRUE(postgres_->CreateDatabase("relmap").ok());
    for (int i = 0; i < 2; ++i) {
      servers_.push_back(
          std::make_unique<ClusterServer>(postgres_->Uri("relmap"), FreeLoopbackPort(),
                                          directory_.path() + "/server" + std::to_string(i)));
      servers_.back()->Start();
      if (HasFatalFailure()) return;
    }
    nginx_ = std::make_unique<NginxProcess>(
        directory_.path() + "/nginx",
        std::vector<std::string>{servers_[0]->Address(), servers_[1]->Address()});
    ASSERT_TRUE(nginx_->Start()) << nginx_->LogTail();
    client_ = std::make_unique<client::RelevanceClient>(nginx_->address());
  }

  // One push cycle through nginx: maps of a fresh cloud, then the outcome of the
  // target (alternating labels, so both classes are learned). When the session moves
  // between the two calls (a server died or came back), the new server does not have
  // the frame (frames live in memory only): FAILED_PRECONDITION, nothing learned, the
  // robot starts again from new maps, as relmap-sim and relmap-robot do.
  void Cycle(ExploredSession& session, std::uint32_t seed) {
    v1::ComputeMapsResponse maps;
    const grpc::Status computed = client_->ComputeMaps(
        session.handle, PackedTabletop(160, 120, seed), &maps, client::PointLabels::kOmit);
    ASSERT_TRUE(computed.ok()) << session.handle.id << ": " << computed.error_message();
    ASSERT_TRUE(maps.has_target_supervoxel_id());
    v1::PostOutcomeResponse outcome;
    const grpc::Status posted = client_->PostOutcome(
        session.handle, maps.frame_id(), maps.target_supervoxel_id(),
        seed % 2 == 0 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE, "", &outcome);
    if (client::IsFrameGone(posted)) {
      ++session.frames_lost;
      return;
    }
    ASSERT_TRUE(posted.ok()) << session.handle.id << ": " << posted.error_message();
    ++session.acknowledged;
  }

  void Cycles(std::vector<ExploredSession>& sessions, int cycles) {
    for (int c = 0; c < cycles; ++c) {
      for (ExploredSession& session : sessions) {
        Cycle(session, seed_++);
        if (HasFatalFailure()) return;
      }
    }
  }

  // Every acknowledged outcome is a sample of the session, whichever server answers.
  void ExpectEveryAcknowledgedSample(const std::vector<ExploredSession>& sessions) {
    for (const ExploredSession& session : sessions) {
      v1::GetSessionResponse got;
      const grpc::Status status = client_->GetSession(session.handle, &got);
      ASSERT_TRUE(status.ok()) << status.error_message();
      EXPECT_EQ(got.stats().moveable_samples() + got.stats().non_moveable_samples(),
                static_cast<std::uint64_t>(session.acknowledged))
          << session.handle.id;
    }
  }

  // Which server served how many of each session's calls so far, for the test's output.
  void PrintCalls(const std::vector<ExploredSession>& sessions, const std::string& phase) {
    std::cout << phase << ":";
    for (const ExploredSession& session : sessions) {
      std::cout << " " << session.handle.id.substr(0, 6) << "="
                << servers_[0]->CallsOn(session.handle.id) << "/"
                << servers_[1]->CallsOn(session.handle.id);
    }
    std::cout << " (calls on server 0/server 1)\n";
  }

  // The server that served `session`'s calls; fails if both did.
  int OwnerOf(const ExploredSession& session) {
    const int on0 = servers_[0]->CallsOn(session.handle.id);
    const int on1 = servers_[1]->CallsOn(session.handle.id);
    EXPECT_TRUE((on0 > 0) != (on1 > 0))
        << session.handle.id << ": " << on0 << " calls on server 0, " << on1 << " on server 1";
    return on0 > 0 ? 0 : 1;
  }

  TemporaryDirectory directory_;
  std::unique_ptr<PostgresInstance> postgres_;
  std::vector<std::unique_ptr<ClusterServer>> servers_;
  std::unique_ptr<NginxProcess> nginx_;
  std::unique_ptr<client::RelevanceClient> client_;
  std::uint32_t seed_ = 1;
};

TEST_F(Cluster, KeepsEachSessionOnOneServerAndSurvivesTheOwnersKill) {
  std::vector<ExploredSession> sessions(kSessions);
  for (ExploredSession& session : sessions) {
    ASSERT_TRUE(client_->CreateSession({}, &session.handle).ok());
  }
  Cycles(sessions, 3);
  ASSERT_FALSE(HasFatalFailure());
  for (const ExploredSession& session : sessions) EXPECT_EQ(session.frames_lost, 0);

  // Affinity: each session's calls all landed on one server.
  int on_server_0 = 0;
  for (const ExploredSession& session : sessions) on_server_0 += OwnerOf(session) == 0 ? 1 : 0;
  RecordProperty("sessions_on_server_0", on_server_0);
  PrintCalls(sessions, "before the kill");
  const int victim = OwnerOf(sessions[0]);
  const int survivor = 1 - victim;

  // kill -9 of a session's owner: its next calls go to the other server, which takes
  // the session over with every acknowledged sample.
  servers_[victim]->Kill();
  ExpectEveryAcknowledgedSample(sessions);
  Cycles(sessions, 2);
  ASSERT_FALSE(HasFatalFailure());
  for (const ExploredSession& session : sessions) {
    EXPECT_GT(servers_[survivor]->CallsOn(session.handle.id), 0) << session.handle.id;
  }
  EXPECT_TRUE(servers_[survivor]->Logged("restored session=" + sessions[0].handle.id));
  PrintCalls(sessions, "after the kill");

  // The killed server comes back on its port; nginx returns its sessions to it once
  // its fail_timeout has passed, and it takes them back from the survivor.
  servers_[victim]->Start();
  ASSERT_FALSE(HasFatalFailure());
  const int calls_before = servers_[victim]->CallsOn(sessions[0].handle.id);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
  while (servers_[victim]->CallsOn(sessions[0].handle.id) == calls_before &&
         std::chrono::steady_clock::now() < deadline) {
    Cycles(sessions, 1);
    ASSERT_FALSE(HasFatalFailure());
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  EXPECT_GT(servers_[victim]->CallsOn(sessions[0].handle.id), calls_before)
      << "the restarted server got no call of its session back";
  Cycles(sessions, 2);
  ASSERT_FALSE(HasFatalFailure());
  PrintCalls(sessions, "after the restart");
  ExpectEveryAcknowledgedSample(sessions);
  // A session moves at most twice (to the survivor, and back), so it loses at most
  // one frame each time.
  for (const ExploredSession& session : sessions) {
    EXPECT_LE(session.frames_lost, 2) << session.handle.id;
    std::cout << session.handle.id.substr(0, 6) << ": " << session.acknowledged
              << " outcomes learned, " << session.frames_lost << " lost with a move\n";
  }
}

// A call that reaches the server not owning the session (past the load balancer, or
// while it routes elsewhere) is turned away with the reason the client library
// repeats it for, naming the owner, and nothing runs.
TEST_F(Cluster, TheServerNotOwningASessionSaysWhoDoes) {
  ExploredSession session;
  ASSERT_TRUE(client_->CreateSession({}, &session.handle).ok());
  Cycle(session, seed_++);  // the serving server now holds the session's lease (2 s)
  ASSERT_FALSE(HasFatalFailure());
  const int other = 1 - OwnerOf(session);
  auto stub = v1::RelevanceService::NewStub(
      grpc::CreateChannel(servers_[other]->Address(), grpc::InsecureChannelCredentials()));
  grpc::ClientContext context;
  context.AddMetadata("authorization", "Bearer " + session.handle.token);
  v1::GetSessionRequest request;
  request.set_session_id(session.handle.id);
  v1::GetSessionResponse response;
  const grpc::Status refused = stub->GetSession(&context, request, &response);
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::UNAVAILABLE) << refused.error_message();
  EXPECT_EQ(client::ReasonOf(refused), v1::SESSION_OWNED_ELSEWHERE) << refused.error_message();
  const std::optional<google::rpc::ErrorInfo> info = client::ErrorInfoOf(refused);
  ASSERT_TRUE(info.has_value());
  std::map<std::string, std::string> metadata(info->metadata().begin(), info->metadata().end());
  EXPECT_EQ(metadata["sessionId"], session.handle.id);
  EXPECT_FALSE(metadata["owner"].empty());
  EXPECT_NE(refused.error_message().find("server \"" + metadata["owner"] + "\""), std::string::npos)
      << refused.error_message();
  EXPECT_FALSE(metadata["leaseExpiresAt"].empty());
  EXPECT_TRUE(client::PushbackOf(context).has_value());
}

// Either server lists every session of the shared store as its owner shows it, from
// the summaries the store keeps: without loading a session (a load logs "restored
// session=") nor taking it, and not as the stale copy a server keeps of a session it
// created and handed over.
TEST_F(Cluster, EitherServerListsEverySessionAsItsOwnerShowsIt) {
  std::vector<ExploredSession> sessions(4);
  for (ExploredSession& session : sessions) {
    ASSERT_TRUE(client_->CreateSession({}, &session.handle).ok());
  }
  Cycles(sessions, 2);
  ASSERT_FALSE(HasFatalFailure());
  std::map<std::string, std::string> owners_stats;
  for (const ExploredSession& session : sessions) {
    v1::GetSessionResponse got;
    ASSERT_TRUE(client_->GetSession(session.handle, &got).ok());
    EXPECT_GT(got.stats().moveable_samples() + got.stats().non_moveable_samples(), 0u);
    owners_stats[session.handle.id] = got.stats().SerializeAsString();
  }
  // A session created on one server and served by the other is loaded by its owner on
  // its first call there: those loads are counted before the listings.
  const int loads[2] = {servers_[0]->LinesLogging("restored session="),
                        servers_[1]->LinesLogging("restored session=")};
  for (const auto& server : servers_) {
    auto stub = v1::RelevanceService::NewStub(
        grpc::CreateChannel(server->Address(), grpc::InsecureChannelCredentials()));
    grpc::ClientContext context;
    v1::ListSessionsResponse listed;
    ASSERT_TRUE(stub->ListSessions(&context, {}, &listed).ok());
    ASSERT_EQ(listed.sessions_size(), static_cast<int>(sessions.size())) << server->Address();
    for (const v1::GetSessionResponse& entry : listed.sessions()) {
      EXPECT_EQ(entry.stats().SerializeAsString(), owners_stats[entry.session_id()])
          << server->Address() << " lists " << entry.session_id() << " as "
          << entry.stats().DebugString();
    }
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(servers_[i]->LinesLogging("restored session="), loads[i]) << "server " << i;
  }
  // Neither took a session by listing it: each session's calls stay on its owner.
  std::vector<int> owners;
  for (const ExploredSession& session : sessions) owners.push_back(OwnerOf(session));
  Cycles(sessions, 1);
  ASSERT_FALSE(HasFatalFailure());
  for (std::size_t i = 0; i < sessions.size(); ++i) {
    EXPECT_EQ(OwnerOf(sessions[i]), owners[i]) << sessions[i].handle.id;
    EXPECT_EQ(sessions[i].frames_lost, 0) << sessions[i].handle.id;
  }
}

}  // namespace
}  // namespace relmap::testing
