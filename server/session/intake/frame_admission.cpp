// A counting semaphore with a bounded number of waiters, served round-robin by session.
// A freed slot goes straight to the next waiter (running_ does not drop), so that a
// call arriving meanwhile cannot take it ahead of those in the queue.
#include "session/intake/frame_admission.h"

#include <algorithm>

namespace relmap::session {

std::optional<FrameAdmission::Ticket> FrameAdmission::Enter(
    std::chrono::system_clock::time_point deadline, std::string_view session) {
  std::unique_lock lock(mutex_);
  if (running_ < concurrent_) {
    ++running_;
    return Ticket(this);
  }
  if (waiting_ >= queued_) return std::nullopt;
  Waiter waiter;
  const std::string key(session);
  std::deque<Waiter*>& queue = waiters_[key];
  if (queue.empty()) turns_.push_back(key);
  queue.push_back(&waiter);
  ++waiting_;
  if (!admitted_.wait_until(lock, deadline, [&] { return waiter.admitted; })) {
    Withdraw(key, &waiter);
    return std::nullopt;
  }
  return Ticket(this);
}

void FrameAdmission::Withdraw(const std::string& session, const Waiter* waiter) {
  const auto it = waiters_.find(session);
  std::erase(it->second, waiter);
  --waiting_;
  if (it->second.empty()) {
    waiters_.erase(it);
    std::erase(turns_, session);
  }
}

void FrameAdmission::Leave() {
  {
    std::lock_guard lock(mutex_);
    if (turns_.empty()) {
      --running_;
      return;
    }
    const std::string session = std::move(turns_.front());
    turns_.pop_front();
    const auto it = waiters_.find(session);
    it->second.front()->admitted = true;  // the slot passes on: running_ stays
    it->second.pop_front();
    --waiting_;
    if (it->second.empty()) {
      waiters_.erase(it);
    } else {
      turns_.push_back(session);  // its next call waits for the others' turns
    }
  }
  // Every waiter checks its own flag; a few dozen at most.
  admitted_.notify_all();
}

std::size_t FrameAdmission::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

std::size_t FrameAdmission::waiting() const {
  std::lock_guard lock(mutex_);
  return waiting_;
}

std::size_t FrameAdmission::queue_bound() const {
  std::lock_guard lock(mutex_);
  return queued_;
}

void FrameAdmission::set_queue_bound(std::size_t queued) {
  std::lock_guard lock(mutex_);
  queued_ = queued;
}

}  // namespace relmap::session
