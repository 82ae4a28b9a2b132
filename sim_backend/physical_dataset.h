// The rows of `relmap-sim dataset --mode physical`: one physical-mode replication, as
// `relmap-sim run --mode physical` runs it, then what its session learned.
#pragma once

#include <cstdio>
#include <vector>

#include "common/status.h"
#include "dataset_options.h"
#include "learned_samples.h"
#include "relevance_client.h"
#include "simulated_scene.h"

namespace relmap::sim {

// Replication 0 of `relmap-sim run --mode physical --seed options.seed --iterations
// options.frames` (the run's defaults otherwise: the target alone, the choice map's
// draw, the visibility change detector) on `scene` through `client`, then the session's
// samples paired with its pushes (learned_samples.h); the session is deleted. A progress
// bar on `progress` unless null. A failed call, or an iteration that failed, ends it
// with its error.
StatusOr<std::vector<LearnedSample>> CollectLearnedSamples(const DatasetOptions& options,
                                                           SimulatedScene& scene,
                                                           client::RelevanceClient& client,
                                                           std::FILE* progress);

}  // namespace relmap::sim
