// The soak of relmap-load (--soak-rounds): rounds of S sessions under load, each followed
// by deleting them and a rest, with the server's resident memory sampled every second
// throughout. What it shows: whether memory plateaus under a steady load, and whether it
// comes back down when the sessions go.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/status.h"
#include "load_cloud.h"
#include "load_driver.h"
#include "relevance_client.h"

namespace relmap::load {

struct SoakPlan {
  int rounds = 4;
  int sessions = 16;
  double rest_seconds = 20;  // after the sessions of a round are deleted
  std::uint64_t seed = 1;    // of the first round's sessions; later rounds go on in its stream
  LoadPlan load;             // of one round (seconds, or cycles per session)
};

struct MemorySample {
  double seconds = 0;  // since the soak started
  double rss_mib = 0;
  int round = 0;      // 1-based
  bool rest = false;  // sampled after the round's sessions were deleted
};

struct SoakRound {
  std::uint64_t cycles = 0;
  double peak_rss_mib = 0;    // while its sessions lived
  double rested_rss_mib = 0;  // at the end of its rest
  std::uint64_t failed_sessions = 0;
};

struct SoakResults {
  double baseline_rss_mib = 0;  // before the first session
  std::vector<MemorySample> samples;
  std::vector<SoakRound> rounds;
  std::string first_failure;
};

// Runs `plan` against the server of `client`, whose memory is read from /proc/`server_pid`.
// `progress` gets one line a second. Errors: the server's memory cannot be read, or a
// round's sessions cannot be created.
StatusOr<SoakResults> RunSoak(client::RelevanceClient& client, pid_t server_pid,
                              const LoadCloud& cloud, const SoakPlan& plan,
                              const std::function<void(const std::string&)>& progress);

// One row per sample: seconds,rss_mib,round,phase.
Status WriteSoakCsv(const SoakResults& results, const std::string& path);
// Resident memory over minutes, the load and the rest phases in two colours.
Status WriteSoakPlot(const SoakResults& results, const std::string& title, const std::string& path);

}  // namespace relmap::load
