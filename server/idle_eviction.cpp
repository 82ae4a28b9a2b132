// A thread that sleeps on a condition variable, so that stopping does not wait out
// a period.
#include "idle_eviction.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

namespace relmap::server {

IdleEviction::IdleEviction(session::SessionRegistry& registry, long long idle_seconds)
    : registry_(registry), idle_seconds_(idle_seconds), thread_([this] { Run(); }) {}

IdleEviction::~IdleEviction() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wakeup_.notify_all();
  thread_.join();
}

void IdleEviction::Run() {
  if (registry_.store() == nullptr || idle_seconds_ <= 0) return;
  const auto period = std::chrono::seconds(std::clamp<long long>(idle_seconds_ / 2, 1, 30));
  std::unique_lock lock(mutex_);
  while (!wakeup_.wait_for(lock, period, [&] { return stopping_; })) {
    const auto now = std::chrono::duration_cast<std::chrono::milliseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    for (const std::string& id : registry_.EvictIdle(now - idle_seconds_ * 1000)) {
      spdlog::info("evicted session={} (idle for {} s)", id, idle_seconds_);
    }
  }
}

}  // namespace relmap::server
