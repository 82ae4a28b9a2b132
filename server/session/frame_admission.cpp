// A counting semaphore with a bounded number of waiters.
#include "session/frame_admission.h"

namespace relmap::session {

std::optional<FrameAdmission::Ticket> FrameAdmission::Enter(
    std::chrono::system_clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  if (running_ < concurrent_) {
    ++running_;
    return Ticket(this);
  }
  if (waiting_ >= queued_) return std::nullopt;
  ++waiting_;
  const bool admitted = freed_.wait_until(lock, deadline, [&] { return running_ < concurrent_; });
  --waiting_;
  if (!admitted) return std::nullopt;
  ++running_;
  return Ticket(this);
}

void FrameAdmission::Leave() {
  {
    std::lock_guard lock(mutex_);
    --running_;
  }
  freed_.notify_one();
}

std::size_t FrameAdmission::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

std::size_t FrameAdmission::waiting() const {
  std::lock_guard lock(mutex_);
  return waiting_;
}

}  // namespace relmap::session
