// The relmap-server that relmap-sim and relmap-robot start when no --server is given.
#pragma once

#include <string>

#include "common/status.h"

namespace relmap::client {

// `flag` when not empty; else relmap-server beside this executable (an installed
// layout), else the one this build made (a compile definition). NOT_FOUND naming the
// places looked at when none is executable.
StatusOr<std::string> FindServerBinary(const std::string& flag);

}  // namespace relmap::client
