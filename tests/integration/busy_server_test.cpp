// A server with more clouds to process than --max-concurrent-frames and
// --max-queued-frames allow turns the rest away at once with RESOURCE_EXHAUSTED and a
// pushback trailer, and the client library waits it out and repeats them.
#include <gtest/gtest.h>

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

TEST(BusyServer, TheClientLibraryRepeatsWhatABusyServerTurnedAway) {
  testing::ServerProcess server({"--max-concurrent-frames", "1", "--max-queued-frames", "1"});
  client::ClientOptions options;
  options.address = server.address();
  options.retry.max_attempts = 100;  // the deadline (30 s) bounds the wait
  client::RelevanceClient client(options);
  client::SessionHandle session;
  ASSERT_TRUE(client.CreateSession({}, &session).ok());
  const v1::Cloud cloud = testing::PackedTabletop(640, 480);
  std::atomic<int> ok = 0;
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i) {
    clients.emplace_back([&] {
      v1::ComputeMapsResponse response;
      const grpc::Status status =
          client.ComputeMaps(session, cloud, &response, client::PointLabels::kOmit);
      EXPECT_TRUE(status.ok()) << status.error_message();
      if (status.ok()) ++ok;
    });
  }
  for (std::thread& t : clients) t.join();
  EXPECT_EQ(ok.load(), kClients);
  EXPECT_GT(client.retries(), 0u);
}

}  // namespace
}  // namespace relmap
