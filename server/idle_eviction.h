// Idle sessions leave memory (the store keeps them) so that memory follows the
// active sessions, not every session ever created; with an expiry set, sessions
// idle for longer end: they are deleted from memory and from the store.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

#include "session/registry/session_registry.h"

namespace relmap::server {

class IdleEviction {
 public:
  // Every min(shortest setting / 2, 30) s (at least 1 s), evicts the sessions idle for
  // `evict_idle_seconds` (only with a store: memory is otherwise their only copy) and
  // deletes those idle for `expire_idle_seconds` (SessionRegistry::ExpireIdle), logging
  // one line per session; a setting <= 0 is off.
  IdleEviction(session::SessionRegistry& registry, long long evict_idle_seconds,
               long long expire_idle_seconds = 0);
  // Stops and joins the thread.
  ~IdleEviction();
  IdleEviction(const IdleEviction&) = delete;
  IdleEviction& operator=(const IdleEviction&) = delete;

 private:
  void Run();

  session::SessionRegistry& registry_;
  const long long evict_idle_seconds_;
  const long long expire_idle_seconds_;
  std::mutex mutex_;
  std::condition_variable wakeup_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace relmap::server
