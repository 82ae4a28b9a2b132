// One replication of an experiment: its own session and its own scene, iterated.
//
// Order inside an iteration (relmap's, docs/method.md §7): capture → ComputeMaps (maps of
// every sample learned so far) → score the relevance map (§6) → choose the target →
// label it (oracle: its ground truth; physical: push, capture again, and the server's
// change detector decides from the two clouds) → PostOutcome, after which the session
// has learned the label. So the map scored at iteration i has learned the samples of
// iterations 1 … i−1; the authors' code scored before learning the previous sample,
// one sample later than this.
#pragma once

#include <functional>

#include "experiment_options.h"
#include "iteration_record.h"
#include "relevance_client.h"
#include "simulated_scene.h"

namespace relmap::sim {

// The one-line statement of the order above, for the summary.
extern const char kIterationOrder[];

// Runs replication `replication` (0-based, seed options.seed + replication) of
// `options` on `scene` through `client`: creates its session, iterates, and writes its
// map snapshots into options.out. `after_iteration` is called after each iteration
// (from the calling thread). A failed call ends the replication early, with the
// error in the result.
ReplicationResult RunReplication(
    const ExperimentOptions& options, int replication, SimulatedScene& scene,
    client::RelevanceClient& client,
    const std::function<void(const IterationRecord&)>& after_iteration);

}  // namespace relmap::sim
