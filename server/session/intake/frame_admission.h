// Admission of the calls that process a whole cloud (ComputeMaps, PostOutcome with an
// after cloud): tens to hundreds of milliseconds of CPU each. At most `concurrent` run
// at once, at most `queued` more wait for a slot, and any other is refused at once; the
// server sizes `queued` from its sessions (server/worker_sizing.h).
// Without it, a full worker pool of frames on a 2-core machine made every call slow
// and starved the 1 ms outcomes, which lost the race for a worker thread to the
// frames (measured with relmap-load at 64 sessions: PostOutcome p99 12–32 s).
// Waiters are served round-robin by session, first come first served within one: a
// session waits for one turn of the sessions ahead of it, however many calls another
// sends. (Waking any waiter, as a bare condition variable does, let some sessions wait
// many turns: at 64 sessions ComputeMaps p99 was 9 s against a p50 of 0.6 s.)
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

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

  // A slot now, or after waiting in the bounded queue until `deadline`, served in the
  // round-robin turn of `session` (calls without one share a turn); nullopt when the
  // queue is full or the deadline passed first.
  std::optional<Ticket> Enter(std::chrono::system_clock::time_point deadline,
                              std::string_view session = {});

  std::size_t running() const;
  std::size_t waiting() const;
  std::size_t queue_bound() const;
  // A new bound on the waiting calls; calls already waiting beyond it keep their place.
  void set_queue_bound(std::size_t queued);

 private:
  struct Waiter {
    bool admitted = false;
  };

  // Hands a freed slot to the next waiter in turn, or frees it.
  void Leave();
  // Takes `waiter` out of its session's queue (it gave up).
  void Withdraw(const std::string& session, const Waiter* waiter);

  const std::size_t concurrent_;
  mutable std::mutex mutex_;
  std::size_t queued_;  // guarded by mutex_
  std::condition_variable admitted_;
  std::size_t running_ = 0;
  std::size_t waiting_ = 0;
  std::map<std::string, std::deque<Waiter*>, std::less<>> waiters_;  // by session, in order
  std::deque<std::string> turns_;  // the sessions with a waiter, next to be served first
};

}  // namespace relmap::session
