// The fake robot controller.
#include "fake_controller.h"

#include <gtest/gtest.h>
#include <sys/socket.h>

namespace relmap::robot {

FakeController::FakeController(std::function<std::string(int request, const std::string&)> answer)
    : answer_(std::move(answer)) {
  StatusOr<UniqueFd> listener = ListenTcp("127.0.0.1:0");
  EXPECT_TRUE(listener.ok()) << listener.status().message();
  listener_ = std::move(listener).value();
  address_ = "127.0.0.1:" + std::to_string(LocalPort(listener_.get()));
  thread_ = std::thread([this] { Serve(); });
}

FakeController::~FakeController() {
  stop_.store(true);
  thread_.join();
}

void FakeController::Serve() {
  while (!stop_.load()) {
    StatusOr<Wait> ready = WaitReadable(listener_.get(), Clock::time_point::max(), &stop_);
    if (!ready.ok() || *ready != Wait::kReady) return;
    UniqueFd connection(::accept(listener_.get(), nullptr, nullptr));
    ++connections_;
    std::string received;
    for (;;) {
      ready = WaitReadable(connection.get(), Clock::time_point::max(), &stop_);
      if (!ready.ok() || *ready != Wait::kReady) return;
      char chunk[4096];
      const ssize_t n = ::recv(connection.get(), chunk, sizeof chunk, 0);
      if (n <= 0) break;
      received.append(chunk, static_cast<std::size_t>(n));
      bool hung_up = false;
      for (std::size_t end; !hung_up && (end = received.find('\n')) != std::string::npos;) {
        const std::string line = received.substr(0, end);
        received.erase(0, end + 1);
        int request = 0;
        {
          const std::lock_guard<std::mutex> lock(mutex_);
          lines_.push_back(line);
          request = static_cast<int>(lines_.size());
        }
        std::string reply = answer_(request, line);
        hung_up = reply.size() >= kHangUp.size() &&
                  reply.compare(reply.size() - kHangUp.size(), kHangUp.size(), kHangUp) == 0;
        if (hung_up) {
          reply.resize(reply.size() - kHangUp.size());
        } else if (!reply.empty()) {
          reply += "\n";
        }
        (void)WriteAll(connection.get(), reply);
      }
      if (hung_up) break;
    }
  }
}

}  // namespace relmap::robot
