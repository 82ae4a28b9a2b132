// The tcp-json driver: a line out, a line back, a deadline, a fresh connection after
// any trouble.
#include "tcp_json_driver.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <csignal>
#include <cstring>

namespace relmap::robot {
namespace {

constexpr std::size_t kMaxReplyBytes = 1 << 20;  // no controller answers a megabyte

}  // namespace

TcpJsonDriver::TcpJsonDriver(std::string address, std::chrono::milliseconds connect_timeout,
                             std::chrono::milliseconds reply_timeout)
    : address_(std::move(address)),
      connect_timeout_(connect_timeout),
      reply_timeout_(reply_timeout) {
  std::signal(SIGPIPE, SIG_IGN);
}

Status TcpJsonDriver::Connect() {
  if (connection_.valid()) {
    // Between two pushes the controller has nothing to say: readable means it closed the
    // connection (or talks out of turn); either way start afresh.
    pollfd idle{connection_.get(), POLLIN, 0};
    if (::poll(&idle, 1, 0) == 0) return OkStatus();
    connection_.reset();
  }
  StatusOr<UniqueFd> connected = ConnectTcp(address_, connect_timeout_);
  if (!connected.ok()) return Status(StatusCode::kUnavailable, connected.status().message());
  connection_ = std::move(connected).value();
  ++connections_;
  return OkStatus();
}

StatusOr<std::string> TcpJsonDriver::ReadLine(Clock::time_point deadline) {
  std::string line;
  for (;;) {
    StatusOr<Wait> ready = WaitReadable(connection_.get(), deadline, nullptr);
    if (!ready.ok()) return ready.status();
    if (*ready != Wait::kReady) {
      return Status(StatusCode::kDeadlineExceeded,
                    "the controller at " + address_ + " did not answer within " +
                        std::to_string(reply_timeout_.count()) + " ms");
    }
    char chunk[4096];
    const ssize_t n = ::recv(connection_.get(), chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      return Status(StatusCode::kUnavailable,
                    "the controller at " + address_ + " closed the connection before answering" +
                        (n < 0 ? std::string(" (") + std::strerror(errno) + ")" : ""));
    }
    line.append(chunk, static_cast<std::size_t>(n));
    const std::size_t end = line.find('\n');
    if (end != std::string::npos) {
      // Anything after the line is out of turn: the connection is not reused.
      if (end + 1 != line.size()) connection_.reset();
      line.resize(end);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    if (line.size() > kMaxReplyBytes) {
      return InvalidArgumentError("the controller's answer has no end of line in its first MiB");
    }
  }
}

StatusOr<PushOutcome> TcpJsonDriver::Push(const DriverRequest& target) {
  if (Status status = Connect(); !status.ok()) return status;
  const Clock::time_point deadline = Clock::now() + reply_timeout_;
  StatusOr<std::string> line = [&]() -> StatusOr<std::string> {
    if (!WriteAll(connection_.get(), DriverRequestJson(target) + "\n")) {
      return Status(StatusCode::kUnavailable, "cannot send the target to the controller at " +
                                                  address_ + ": " + std::strerror(errno));
    }
    return ReadLine(deadline);
  }();
  StatusOr<PushOutcome> outcome = line.ok() ? ParseDriverResult(*line) : line.status();
  if (!outcome.ok()) connection_.reset();
  return outcome;
}

}  // namespace relmap::robot
