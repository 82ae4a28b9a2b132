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
  // The bound of the worker threads, which may be moved while the server runs.
  std::unique_ptr<grpc::ResourceQuota> quota;
};

// Started on at most `threads` worker threads and reporting SERVING; UNAVAILABLE when it
// cannot listen. A TLS certificate or key that cannot be read ends the process
// (tools::ExitWithError).
StatusOr<Serving> StartServing(const ServerOptions& options, int threads, grpc::Service& service);

}  // namespace relmap::server
