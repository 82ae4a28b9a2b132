// One relmap-server for a whole test suite (started in SetUpTestSuite, stopped in
// TearDownTestSuite), and a client to it: suites whose tests each open their own
// sessions need no server of their own per test.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <utility>

#include "local_server.h"
#include "relevance_client.h"

namespace relmap::testing {

class SuiteServer {
 public:
  // Starts RELMAP_SERVER_BINARY with `options`; fails the suite if it does not start.
  void Start(const client::LocalServerOptions& options) {
    StatusOr<std::unique_ptr<client::LocalServer>> started =
        client::LocalServer::Start(RELMAP_SERVER_BINARY, options);
    ASSERT_TRUE(started.ok()) << started.status().message();
    server_ = std::move(started).value();
    client_ = std::make_unique<client::RelevanceClient>(server_->address());
  }
  void Stop() {
    client_.reset();
    server_.reset();
  }

  client::LocalServer& server() { return *server_; }
  client::RelevanceClient& client() { return *client_; }

 private:
  std::unique_ptr<client::LocalServer> server_;
  std::unique_ptr<client::RelevanceClient> client_;
};

}  // namespace relmap::testing
