// A pusher driver that talks to a robot controller over TCP in JSON lines: per push
// one line with the target (DriverRequest, as the exec driver's stdin gets it), one
// line back with the result (DriverResult, as an exec driver prints it). One
// connection serves every push; it is opened again when it was dropped.
#pragma once

#include <chrono>
#include <string>

#include "posix_io.h"
#include "pusher_driver.h"

namespace relmap::robot {

class TcpJsonDriver final : public PusherDriver {
 public:
  // `address` is the controller's "host:port". Ignores SIGPIPE in this process, so that
  // a connection closed by the controller is an error, not a crash.
  TcpJsonDriver(std::string address, std::chrono::milliseconds connect_timeout,
                std::chrono::milliseconds reply_timeout);

  // UNAVAILABLE when the controller cannot be reached within the connect timeout or
  // closes the connection before answering; DEADLINE_EXCEEDED when no line comes back
  // within the reply timeout; INVALID_ARGUMENT when the line is not a DriverResult.
  // After any error the connection is closed, so that a late answer is never taken for
  // the next push's.
  StatusOr<PushOutcome> Push(const DriverRequest& target) override;

  // Connections opened so far.
  int connections() const { return connections_; }

 private:
  // A live connection: the current one unless the controller has closed it (or sent
  // something unasked), else a new one.
  Status Connect();
  // One line from the controller, without its newline, by `deadline`.
  StatusOr<std::string> ReadLine(Clock::time_point deadline);

  std::string address_;
  std::chrono::milliseconds connect_timeout_;
  std::chrono::milliseconds reply_timeout_;
  UniqueFd connection_;
  int connections_ = 0;
};

}  // namespace relmap::robot
