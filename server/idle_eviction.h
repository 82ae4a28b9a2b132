// Idle sessions leave memory (the store keeps them) so that memory follows the
// active sessions, not every session ever created.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

#include "session/session_registry.h"

namespace relmap::server {

class IdleEviction {
 public:
  // Every min(idle_seconds / 2, 30) s (at least 1 s), evicts the sessions idle for
  // `idle_seconds`; does nothing without a store or with idle_seconds <= 0.
  IdleEviction(session::SessionRegistry& registry, long long idle_seconds);
  // Stops and joins the thread.
  ~IdleEviction();
  IdleEviction(const IdleEviction&) = delete;
  IdleEviction& operator=(const IdleEviction&) = delete;

 private:
  void Run();

  session::SessionRegistry& registry_;
  const long long idle_seconds_;
  std::mutex mutex_;
  std::condition_variable wakeup_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace relmap::server
