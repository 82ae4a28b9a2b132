// A gRPC server in the test process on a free loopback port, for client tests that
// fake the relevance server.
#pragma once

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace relmap::client {

// `service` (not owned, must outlive the server) served on 127.0.0.1; `address`
// receives host:port. Null, with a test failure, if the server did not start.
inline std::unique_ptr<grpc::Server> StartInProcessServer(grpc::Service* service,
                                                          std::string* address) {
  grpc::ServerBuilder builder;
  int port = 0;
  builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(), &port);
  builder.RegisterService(service);
  std::unique_ptr<grpc::Server> server = builder.BuildAndStart();
  EXPECT_NE(port, 0) << "the in-process server did not start";
  *address = "127.0.0.1:" + std::to_string(port);
  return port == 0 ? nullptr : std::move(server);
}

}  // namespace relmap::client
