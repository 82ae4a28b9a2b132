// relmap-server's gRPC server: the service, health and reflection, on the listen
// address of the options, in plaintext or TLS, on a bounded pool of threads.
#pragma once

#include <grpcpp/grpcpp.h>

#include <memory>

#include "common/status.h"
#include "server_options.h"

namespace relmap::server {

struct Serving {
  std::unique_ptr<grpc::Server> server;
  int port = 0;  // the port bound, also when the options asked for port 0
};

// Started and reporting SERVING; UNAVAILABLE when it cannot listen. A TLS
// certificate or key that cannot be read ends the process (tools::ExitWithError).
StatusOr<Serving> StartServing(const ServerOptions& options, grpc::Service& service);

}  // namespace relmap::server
