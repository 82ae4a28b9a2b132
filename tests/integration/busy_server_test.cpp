// A server with more clouds to process than --max-concurrent-frames and
// --max-queued-frames allow turns the rest away at once with RESOURCE_EXHAUSTED and a
// pushback trailer, and the client library waits it out and repeats them; a call that
// waits longer than --max-frame-wait-ms is turned away too.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "integration/server_process.h"
#include "integration/test_support.h"
#include "relevance_client.h"

namespace relmap {
namespace {

constexpr int kClients = 6;

TEST(BusyServer, TurnsCloudsAwayBeyondItsQueueWithAPushback) {
  testing::ServerProcess server({"--max-concurrent-frames", "1", "--max-queued-frames", "1"});
  client::RelevanceClient client(server.address());
  client::SessionHandle session;
  ASSERT_TRUE(client.CreateSession({}, &session).ok());
  const v1::Cloud cloud = testing::PackedTabletop(640, 480);  // ~0.25 s of work a call
  auto stub = v1::RelevanceService::NewStub(server.Channel());
  std::atomic<int> ok = 0, busy = 0, other = 0;
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i) {
    clients.emplace_back([&] {
      grpc::ClientContext context;
      context.AddMetadata("authorization", "Bearer " + session.token);
      v1::ComputeMapsRequest request;
      request.set_session_id(session.id);
      *request.mutable_cloud() = cloud;
      request.set_omit_point_labels(true);
      v1::ComputeMapsResponse response;
      const grpc::Status status = stub->ComputeMaps(&context, request, &response);
      if (status.ok()) {
        ++ok;
      } else if (status.error_code() == grpc::StatusCode::RESOURCE_EXHAUSTED &&
                 status.error_message().rfind("busy: ", 0) == 0 &&
                 client::PushbackOf(context).has_value()) {
        ++busy;
        // The reason says it too, with the trailer's wait.
        EXPECT_EQ(client::ReasonOf(status), v1::BUSY);
        const std::optional<google::rpc::ErrorInfo> info = client::ErrorInfoOf(status);
        EXPECT_TRUE(info.has_value() && info->metadata().count("retryAfterMs") == 1 &&
                    info->metadata().at("retryAfterMs") ==
                        std::to_string(client::PushbackOf(context)->count()));
      } else {
        ++other;
      }
    });
  }
  for (std::thread& t : clients) t.join();
  EXPECT_GE(ok.load(), 2);  // the one running and the one queued
  EXPECT_GT(busy.load(), 0);
  EXPECT_EQ(other.load(), 0);
}

// What happened to kClients clouds sent at once through the client library, which
// repeats a call a busy server turned away until it is served.
struct SentAtOnce {
  int served = 0;
  std::size_t turned_away = 0;  // the repeats
};

SentAtOnce SendCloudsAtOnce(const std::vector<std::string>& server_flags) {
  testing::ServerProcess server(server_flags);
  client::RelevanceClient client(server.address());
  client::SessionHandle session;
  EXPECT_TRUE(client.CreateSession({}, &session).ok());
  const v1::Cloud cloud = testing::PackedTabletop(320, 240);
  std::atomic<int> served = 0;
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i) {
    clients.emplace_back([&] {
      v1::ComputeMapsResponse response;
      // Whether every call must be served is the caller's to say: one the server keeps
      // turning away may run out of the client's repeats on a slow machine.
      if (client.ComputeMaps(session, cloud, &response, client::PointLabels::kOmit).ok()) {
        ++served;
      }
    });
  }
  for (std::thread& t : clients) t.join();
  return {.served = served.load(), .turned_away = client.retries()};
}

TEST(BusyServer, ACallWaitsForItsTurnUpToTheLongestWait) {
  // One slot and room for every other call to wait: with the default wait (60 s)
  // each waits its turn; with 1 ms, each waiting call is turned away.
  const std::vector<std::string> queue = {"--max-concurrent-frames", "1", "--max-queued-frames",
                                          std::to_string(kClients)};
  const SentAtOnce patient = SendCloudsAtOnce(queue);
  EXPECT_EQ(patient.served, kClients);
  EXPECT_EQ(patient.turned_away, 0u);
  // Turned away, the calls are repeated; whether all are served in the client's repeats
  // depends on how long a frame takes (under TSan, ~4 s each: some were not).
  std::vector<std::string> impatient = queue;
  impatient.insert(impatient.end(), {"--max-frame-wait-ms", "1"});
  EXPECT_GT(SendCloudsAtOnce(impatient).turned_away, 0u);
}

TEST(BusyServer, TheClientLibraryRepeatsWhatABusyServerTurnedAway) {
  const SentAtOnce sent =
      SendCloudsAtOnce({"--max-concurrent-frames", "1", "--max-queued-frames", "1"});
  EXPECT_EQ(sent.served, kClients);
  EXPECT_GT(sent.turned_away, 0u);
}

// Without a flag the server sizes its pool from its sessions (server/worker_sizing.h):
// 24 robots, each sending a frame at once, all wait their turn and none is turned away.
// With the old fixed pool (16 threads, 8 waiting) most were.
TEST(BusyServer, ByDefaultEverySessionsFrameWaitsItsTurn) {
  constexpr int kSessions = 24;
  testing::ServerProcess server({"--max-concurrent-frames", "1"});
  client::RelevanceClient client(server.address());
  std::vector<client::SessionHandle> sessions(kSessions);
  for (client::SessionHandle& session : sessions) {
    ASSERT_TRUE(client.CreateSession({}, &session).ok());
  }
  const v1::Cloud cloud = testing::PackedTabletop(160, 120);
  auto stub = v1::RelevanceService::NewStub(server.Channel());
  std::atomic<int> ok = 0;
  std::vector<grpc::StatusCode> refused(kSessions, grpc::StatusCode::OK);
  std::vector<std::thread> robots;
  for (int i = 0; i < kSessions; ++i) {
    robots.emplace_back([&, i] {
      grpc::ClientContext context;
      context.AddMetadata("authorization", "Bearer " + sessions[i].token);
      v1::ComputeMapsRequest request;
      request.set_session_id(sessions[i].id);
      *request.mutable_cloud() = cloud;
      request.set_omit_point_labels(true);
      v1::ComputeMapsResponse response;
      const grpc::Status status = stub->ComputeMaps(&context, request, &response);
      if (status.ok()) {
        ++ok;
      } else {
        refused[i] = status.error_code();
      }
    });
  }
  for (std::thread& t : robots) t.join();
  EXPECT_EQ(ok.load(), kSessions);
  EXPECT_EQ(std::count(refused.begin(), refused.end(), grpc::StatusCode::RESOURCE_EXHAUSTED), 0);
}

}  // namespace
}  // namespace relmap
