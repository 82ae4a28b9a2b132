// A thread that sleeps on a condition variable, so that stopping does not wait out
// a period.
#include "idle_eviction.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

namespace relmap::server {

IdleEviction::IdleEviction(session::SessionRegistry& registry, long long evict_idle_seconds,
                           long long expire_idle_seconds)
    : registry_(registry),
      evict_idle_seconds_(registry.store() == nullptr ? 0 : evict_idle_seconds),
      expire_idle_seconds_(expire_idle_seconds),
      thread_([this] { Run(); }) {}

IdleEviction::~IdleEviction() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wakeup_.notify_all();
  thread_.join();
}

void IdleEviction::Run() {
  const bool evict = evict_idle_seconds_ > 0;
  const bool expire = expire_idle_seconds_ > 0;
  if (!evict && !expire) return;
  const long long shortest = !evict    ? expire_idle_seconds_
                             : !expire ? evict_idle_seconds_
                                       : std::min(evict_idle_seconds_, expire_idle_seconds_);
  const auto period = std::chrono::seconds(std::clamp<long long>(shortest / 2, 1, 30));
  std::unique_lock lock(mutex_);
  while (!wakeup_.wait_for(lock, period, [&] { return stopping_; })) {
    const auto now = std::chrono::duration_cast<std::chrono::milliseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    if (expire) {
      for (const std::string& id : registry_.ExpireIdle(now - expire_idle_seconds_ * 1000, now)) {
        spdlog::info("expired session={} (idle for {} s): deleted", id, expire_idle_seconds_);
      }
    }
    if (!evict) continue;
    for (const std::string& id : registry_.EvictIdle(now - evict_idle_seconds_ * 1000)) {
      spdlog::info("evicted session={} (idle for {} s)", id, evict_idle_seconds_);
    }
  }
}

}  // namespace relmap::server
