// Small POSIX pieces shared by the drivers and sources that talk over pipes and
// sockets: an owned descriptor, deadlines, whole writes, TCP connect and listen.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::robot {

using Clock = std::chrono::steady_clock;

// A file descriptor, closed when it goes.
class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(UniqueFd&& other) noexcept : fd_(other.release()) {}
  UniqueFd& operator=(UniqueFd&& other) noexcept;
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  ~UniqueFd() { reset(); }

  int get() const { return fd_; }
  bool valid() const { return fd_ >= 0; }
  int release();
  void reset(int fd = -1);

 private:
  int fd_ = -1;
};

// What is left of `deadline`, in whole milliseconds, never negative.
int MillisecondsLeft(Clock::time_point deadline);

// Writes all of `data` to `fd`; false on any error (EPIPE included: callers ignore
// SIGPIPE).
bool WriteAll(int fd, std::string_view data);

// Waits until `fd` is readable (or at its end). kStopped when `stop` is set first,
// kTimedOut past `deadline` (Clock::time_point::max(): none). Wakes every 100 ms to
// look at `stop`.
enum class Wait { kReady, kTimedOut, kStopped };
StatusOr<Wait> WaitReadable(int fd, Clock::time_point deadline, const std::atomic<bool>* stop);

// A TCP connection to "host:port" within `timeout`; UNAVAILABLE when nothing answers.
StatusOr<UniqueFd> ConnectTcp(const std::string& address, std::chrono::milliseconds timeout);
// A socket listening on "host:port" (port 0: any free one); INVALID_ARGUMENT for a
// malformed address, UNAVAILABLE when it cannot be bound.
StatusOr<UniqueFd> ListenTcp(const std::string& address);
// The local port of a bound socket.
int LocalPort(int fd);

}  // namespace relmap::robot
