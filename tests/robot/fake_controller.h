// A fake robot controller for the tcp-json driver's tests: a loopback listener that
// answers each line it receives as the test says.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "posix_io.h"

namespace relmap::robot {

// A controller: per line received, `answer(request, line)` says what to send back (""
// to stay silent; ending in kHangUp: send the rest as is, then close the connection).
// It records every line.
class FakeController {
 public:
  static inline const std::string kHangUp = "<hang up>";

  explicit FakeController(std::function<std::string(int request, const std::string&)> answer);
  ~FakeController();

  const std::string& address() const { return address_; }
  int connections() const { return connections_.load(); }
  std::vector<std::string> lines() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return lines_;
  }

 private:
  void Serve();

  std::function<std::string(int, const std::string&)> answer_;
  UniqueFd listener_;
  std::string address_;
  std::atomic<bool> stop_{false};
  std::atomic<int> connections_{0};
  std::mutex mutex_;
  std::vector<std::string> lines_;
  std::thread thread_;
};

}  // namespace relmap::robot
