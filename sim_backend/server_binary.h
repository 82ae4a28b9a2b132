// The relmap-server that `relmap-sim run` starts when no --server is given.
#pragma once

#include <string>

#include "common/status.h"

namespace relmap::sim {

// `flag` when not empty; else relmap-server beside this executable (an installed
// layout), else the one this build made (a compile definition). NOT_FOUND naming the
// places looked at when none is executable.
StatusOr<std::string> FindServerBinary(const std::string& flag);

}  // namespace relmap::sim
