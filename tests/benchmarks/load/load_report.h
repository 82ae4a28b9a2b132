// The figures of one relmap-load run, as a text report or as one JSON object.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "load_driver.h"
#include "process_memory.h"

namespace relmap::load {

struct LoadReport {
  // What was run.
  int sessions = 0;
  std::uint64_t cycles_per_session = 0;  // 0: until the time limit
  double seconds_limit = 0;              // 0: none
  std::uint64_t seed = 0;
  std::string cloud;
  std::string server;  // the binary started, or the address attached to
  bool server_started = false;
  int server_max_threads = 0;  // 0: the server's default
  bool server_memory_only = false;
  // The server's memory before the sessions were created, after, after the run
  // and after the sessions were deleted; unset when its pid is unknown.
  std::optional<ProcessMemory> before, after_sessions, after_run, after_delete;
  LoadResults results;
};

void PrintTextReport(std::FILE* out, const LoadReport& report);
// One line, one object; NaN (a latency with no sample) is written as null.
void PrintJsonReport(std::FILE* out, const LoadReport& report);

}  // namespace relmap::load
