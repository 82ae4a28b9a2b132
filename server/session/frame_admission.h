// Admission of the calls that process a whole cloud (ComputeMaps, PostOutcome with an
// after cloud): tens to hundreds of milliseconds of CPU each. At most `concurrent` run
// at once, at most `queued` more wait for a slot, and any other is refused at once.
// Without it, a full worker pool of frames on a 2-core machine made every call slow
// and starved the 1 ms outcomes, which lost the race for a worker thread to the
// frames (measured with relmap-load at 64 sessions: PostOutcome p99 12–32 s).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>

namespace relmap::session {

class FrameAdmission {
 public:
  FrameAdmission(std::size_t concurrent, std::size_t queued)
      : concurrent_(concurrent), queued_(queued) {}

  // A running slot, released when the ticket is destroyed.
  class Ticket {
   public:
    explicit Ticket(FrameAdmission* admission) : admission_(admission) {}
    Ticket(Ticket&& other) noexcept : admission_(other.admission_) { other.admission_ = nullptr; }
    Ticket(const Ticket&) = delete;
    Ticket& operator=(const Ticket&) = delete;
    Ticket& operator=(Ticket&&) = delete;
    ~Ticket() {
      if (admission_ != nullptr) admission_->Leave();
    }

   private:
    FrameAdmission* admission_;
  };

  // A slot now, or after waiting in the bounded queue until `deadline`; nullopt when
  // the queue is full or the deadline passed first.
  std::optional<Ticket> Enter(std::chrono::system_clock::time_point deadline);

  std::size_t running() const;
  std::size_t waiting() const;

 private:
  void Leave();

  const std::size_t concurrent_;
  const std::size_t queued_;
  mutable std::mutex mutex_;
  std::condition_variable freed_;
  std::size_t running_ = 0;
  std::size_t waiting_ = 0;
};

}  // namespace relmap::session
