// A whole `relmap-sim run` once the server is reachable: the replications as parallel
// sessions, then the CSVs, the summary and the plots.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/status.h"
#include "experiment_options.h"
#include "iteration_record.h"
#include "relevance_client.h"
#include "simulated_scene.h"

namespace relmap::sim {

// A new instance of scene `name_or_path` drawn from `seed` (OdeScene::Load for the
// shipped scenes; tests give analytic ones).
using SceneFactory = std::function<StatusOr<std::unique_ptr<SimulatedScene>>(
    const std::string& name_or_path, std::uint64_t seed)>;

struct ExperimentRun {
  std::vector<ReplicationResult> replications;  // in replication order
  double elapsed_seconds = 0;
};

// Runs options.replications replications on up to options.parallel threads, each with
// its own session and its own scene (`make_scene(options.scene, options.seed + r)`,
// created, used and destroyed on the thread that runs it), and writes every output
// file into options.out (created if missing). `server` is the address, for the
// summary. A progress bar over all iterations goes to `progress` unless it is null.
// Errors of single replications are in their results; the status is not ok when an
// output file cannot be written.
StatusOr<ExperimentRun> RunExperiment(const ExperimentOptions& options,
                                      const SceneFactory& make_scene,
                                      client::RelevanceClient& client, const std::string& server,
                                      bool server_started, std::FILE* progress);

}  // namespace relmap::sim
