// The resident memory of a process, as Linux reports it in /proc/<pid>/status.
#pragma once

#include <sys/types.h>

#include <cstdint>

#include "common/status.h"

namespace relmap::load {

struct ProcessMemory {
  std::int64_t rss_kib = 0;       // VmRSS: resident now
  std::int64_t peak_rss_kib = 0;  // VmHWM: the most it has been resident
};

// NOT_FOUND when the process does not exist (or has exited).
StatusOr<ProcessMemory> ReadProcessMemory(pid_t pid);

}  // namespace relmap::load
