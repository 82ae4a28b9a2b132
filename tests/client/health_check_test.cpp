// RelevanceClient::CheckHealth (and so `relmap health`) reads grpc.health.v1 as
// load balancers and probes do: SERVING, then NOT_SERVING once the server drains.
#include <grpcpp/health_check_service_interface.h>
#include <gtest/gtest.h>

#include <chrono>

#include "client/in_process_server.h"
#include "relevance_client.h"

namespace relmap::client {
namespace {

using grpc::health::v1::HealthCheckResponse;

class HealthCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    grpc::EnableDefaultHealthCheckService(true);
    server_ = StartInProcessServer(&service_, &address_);
    ASSERT_NE(server_, nullptr);
  }
  void TearDown() override {
    if (server_) server_->Shutdown();
  }

  v1::RelevanceService::Service service_;  // every method UNIMPLEMENTED: health only
  std::unique_ptr<grpc::Server> server_;
  std::string address_;
};

TEST_F(HealthCheck, ARunningServerIsServing) {
  RelevanceClient client(address_);
  HealthCheckResponse response;
  ASSERT_TRUE(client.CheckHealth("", &response).ok());
  EXPECT_EQ(response.status(), HealthCheckResponse::SERVING);
}

TEST_F(HealthCheck, ADrainingServerIsNotServing) {
  server_->GetHealthCheckService()->SetServingStatus(false);
  RelevanceClient client(address_);
  HealthCheckResponse response;
  ASSERT_TRUE(client.CheckHealth("", &response).ok());
  EXPECT_EQ(response.status(), HealthCheckResponse::NOT_SERVING);
}

TEST_F(HealthCheck, AnUnknownServiceIsNotFound) {
  RelevanceClient client(address_);
  HealthCheckResponse response;
  EXPECT_EQ(client.CheckHealth("no.such.Service", &response).error_code(),
            grpc::StatusCode::NOT_FOUND);
}

TEST_F(HealthCheck, NoServerIsAnErrorWithinTheDeadline) {
  server_->Shutdown();
  server_.reset();
  ClientOptions options;
  options.address = address_;
  options.deadline = std::chrono::milliseconds(300);
  RelevanceClient client(options);
  HealthCheckResponse response;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(client.CheckHealth("", &response).ok());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

}  // namespace
}  // namespace relmap::client
