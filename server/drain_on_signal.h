// The graceful stop: on SIGTERM or SIGINT, NOT_SERVING first, while calls are still
// served, so that load balancers and Kubernetes move traffic away before the server
// refuses it; then, after the drain, a shutdown that lets in-flight calls finish.
#pragma once

#include <grpcpp/grpcpp.h>

#include <thread>

#include "stop_signals.h"

namespace relmap::server {

class DrainOnSignal {
 public:
  DrainOnSignal(StopSignals& signals, grpc::Server& server, long long drain_seconds);
  // Joins the waiting thread: construct it before server.Wait(), which returns
  // once the shutdown it starts is done.
  ~DrainOnSignal();
  DrainOnSignal(const DrainOnSignal&) = delete;
  DrainOnSignal& operator=(const DrainOnSignal&) = delete;

 private:
  std::thread thread_;
};

}  // namespace relmap::server
