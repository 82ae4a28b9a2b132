// The command line of relmap-load.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace relmap::load {

struct LoadOptions {
  int sessions = 8;
  // Push cycles per session; 0 (the default with --seconds alone): until the time is up.
  std::uint64_t cycles = 20;
  double seconds = 0;  // 0: no time limit
  std::uint64_t seed = 1;
  // The cloud: a PCD file when `cloud_path` is set, else the synthetic tabletop.
  std::string cloud_path;
  std::uint32_t synthetic_width = 320;
  std::uint32_t synthetic_height = 240;
  // Start this binary (the default) ...
  std::string server_binary;
  int server_max_threads = 0;  // --max-threads for it; 0: the server's default
  bool memory_only = false;    // start it without --data-dir
  // ... or attach to a running server; its pid is needed for the memory figures.
  std::string server_address;
  pid_t server_pid = 0;
  std::string admin_key_file;
  int max_attempts = 0;  // 0: as many as the deadline allows
  double deadline_seconds = 120;
  bool json = false;
  // The soak (soak.h), when soak_rounds > 0: rounds of `sessions` sessions for `seconds`
  // (or `cycles`) each, their deletion, then rest_seconds of rest.
  int soak_rounds = 0;
  double rest_seconds = 20;
  std::string csv_path;  // the memory samples
  std::string png_path;  // their plot
  // Fail (exit 1) when memory after the last rest exceeds the baseline by more; < 0: no check.
  double max_rested_growth_mib = -1;
};

// The options of `argv`; prints the usage and exits on --help (0) or bad input (2).
// `default_server_binary` is the relmap-server built with this program.
LoadOptions ParseLoadOptions(int argc, char** argv, const std::string& default_server_binary);

}  // namespace relmap::load
