// The command line of relmap-chaos.
#pragma once

#include <cstdint>
#include <string>

namespace relmap::chaos {

// Which servers a run kills.
enum class StoreKind {
  kSqlite,    // one relmap-server on its SQLite file (--data-dir)
  kPostgres,  // one relmap-server on a PostgreSQL database
  kCluster,   // two relmap-servers sharing PostgreSQL behind nginx (deploy/nginx)
  // One relmap-server without a store: a restart loses every session, so a run must
  // report losses and fail. The check's negative control.
  kMemory,
};

struct ChaosOptions {
  StoreKind store = StoreKind::kSqlite;
  int cycles = 20;  // kill -9 and restarts
  int sessions = 8;
  // Writes (outcomes and AddSamples calls) every session has acknowledged between
  // two kills: the kills come as progress is made, not on a clock.
  int writes_per_cycle = 3;
  int samples_per_batch = 4;
  std::uint64_t seed = 1;  // the sessions' seeds and the pauses before each kill
  // The synthetic tabletop every ComputeMaps uploads.
  std::uint32_t cloud_width = 160;
  std::uint32_t cloud_height = 120;
  std::string server_binary;
  // Where the store, the servers' and nginx's logs go; empty: a temporary directory,
  // removed after a run that found nothing wrong.
  std::string directory;
};

// The options of `argv`; prints the usage and exits on --help (0) or bad input (2).
ChaosOptions ParseChaosOptions(int argc, char** argv, const std::string& default_server_binary);

}  // namespace relmap::chaos
