// A pusher driver that runs a user command per push: the target as one JSON object
// (DriverRequest) on its stdin, one JSON object (DriverResult) expected on its stdout,
// e.g. {"result": "done", "label": "moved", "message": "pushed 5 cm"}.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "pusher_driver.h"

namespace relmap::robot {

class ExecDriver final : public PusherDriver {
 public:
  // `command` is argv (no shell). The command runs in its own process group, which is
  // killed when it has not answered within `timeout`. Ignores SIGPIPE in this process,
  // so that a command that exits without reading its stdin is an error, not a crash.
  ExecDriver(std::vector<std::string> command, std::chrono::milliseconds timeout);

  // DEADLINE_EXCEEDED on a timeout, UNKNOWN when the command cannot start or exits
  // non-zero, INVALID_ARGUMENT when its output is not a valid DriverResult.
  StatusOr<PushOutcome> Push(const DriverRequest& target) override;

 private:
  std::vector<std::string> command_;
  std::chrono::milliseconds timeout_;
};

}  // namespace relmap::robot
