// A server told to stop behind a load balancer: SIGTERM turns its health to
// NOT_SERVING at once while it still answers calls for --drain-seconds, then it stops.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <memory>
#include <thread>

#include "local_server.h"
#include "relevance_client.h"

namespace relmap::testing {
namespace {

TEST(Drain, ReportsNotServingForTheServerAndItsServiceAndKeepsAnsweringUntilTheDrainEnds) {
  client::LocalServerOptions options;
  options.memory_only = true;
  options.extra_arguments = {"--drain-seconds", "2"};
  auto server = client::LocalServer::Start(RELMAP_SERVER_BINARY, options);
  ASSERT_TRUE(server.ok()) << server.status().message();
  auto client = std::make_unique<client::RelevanceClient>((*server)->address());
  grpc::health::v1::HealthCheckResponse health;
  constexpr char kService[] = "relmap.v1.RelevanceService";
  for (const std::string service : {"", kService}) {
    ASSERT_TRUE(client->CheckHealth(service, &health).ok()) << service;
    EXPECT_EQ(health.status(), grpc::health::v1::HealthCheckResponse::SERVING) << service;
  }
  client::SessionHandle session;
  ASSERT_TRUE(client->CreateSession({}, &session).ok());

  const auto terminated = std::chrono::steady_clock::now();
  ::kill((*server)->pid(), SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  for (const std::string service : {"", kService}) {
    ASSERT_TRUE(client->CheckHealth(service, &health).ok()) << service;
    EXPECT_EQ(health.status(), grpc::health::v1::HealthCheckResponse::NOT_SERVING) << service;
  }
  v1::GetSessionResponse got;
  EXPECT_TRUE(client->GetSession(session, &got).ok()) << "a draining server still answers";

  client.reset();  // an open connection would hold the stop back
  const int status = (*server)->Stop();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - terminated).count();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_GE(seconds, 2.0);
  EXPECT_LT(seconds, 8.0);
}

}  // namespace
}  // namespace relmap::testing
