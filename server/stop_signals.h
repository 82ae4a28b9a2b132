// SIGINT and SIGTERM, blocked in every thread and awaited by one: gRPC's threads
// must never receive them, or the process would die instead of draining.
#pragma once

#include <csignal>

namespace relmap::server {

class StopSignals {
 public:
  // Blocks the signals in this thread and every thread it starts from now on; call
  // it before gRPC starts its threads.
  static StopSignals Block();

  // Waits for one of them and returns its number.
  int Wait();

 private:
  StopSignals() = default;
  sigset_t signals_{};
};

}  // namespace relmap::server
