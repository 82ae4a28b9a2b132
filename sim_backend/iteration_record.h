// What the runner records about one iteration of one replication: the scores of the
// map it was shown, what it pushed and learned, the session's state afterwards, and
// where the time went. One row of replication-<r>.csv.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/metrics.h"
#include "ground_truth.h"
#include "simulated_scene.h"

namespace relmap::sim {

// Wall-clock milliseconds of the stages of one iteration, as the client sees them.
struct IterationTimings {
  double respawn_ms = 0;      // oracle mode: the re-spawn and settling of the objects
  double capture_ms = 0;      // render and packing of the frame
  double maps_ms = 0;         // the ComputeMaps call, round trip
  double server_maps_ms = 0;  // of which inside the server (StageTimings.total_ms)
  double evaluation_ms = 0;   // ground truth, both scores and the target choice
  double snapshot_ms = 0;     // PNGs of the maps, at snapshot iterations only
  double push_ms = 0;         // physical mode: the push and the after-push render
  double outcome_ms = 0;      // the PostOutcome call, round trip
  double iteration_ms = 0;    // all of the above and the bookkeeping around it
};

// The session's statistics after the iteration (PostOutcomeResponse.stats).
struct ModelCounts {
  std::uint64_t moveable_samples = 0;
  std::uint64_t non_moveable_samples = 0;
  std::uint32_t moveable_components = 0;
  std::uint32_t non_moveable_components = 0;
};

struct IterationRecord {
  int iteration = 0;  // 1-based
  std::size_t supervoxels = 0;
  // The scores (§6) of the relevance map computed at this iteration, before its
  // own outcome was learned.
  metrics::Scores thresholded;
  metrics::Scores soft;
  // The pushed supervoxel; unset when the frame had no usable one.
  std::optional<std::uint32_t> target;
  // The label the session learned (true = moveable) and the ground truth of the
  // target; both unset when no outcome was learned (no target, a physical push the
  // simulator could not execute, or a server that no longer had the frame).
  std::optional<bool> label;
  std::optional<bool> truth;
  // Learned labels that differ from the ground truth of their target, so far.
  std::uint64_t mislabelled = 0;
  // Supervoxels learned beside their target (--labels object), so far, and of those the
  // change detector saw move (physical mode), the ones whose ground truth is not moveable.
  std::uint64_t moved_learned = 0;
  std::uint64_t moved_mislabelled = 0;
  // Oracle mode: objects this iteration's respawn left out of the scene.
  int objects_left_out = 0;
  ModelCounts model;
  // Physical mode with a target: what the simulator says the push did.
  std::optional<PushReport> push;
  // Physical mode, an executed push: how many of the target's points it displaced.
  std::optional<SupervoxelDisplacement> displacement;
  // Physical mode: the server's change detector's evidence for the label, as answered.
  std::optional<v1::ChangeEvidence> change;
  IterationTimings timings;
};

// One replication: its session, its seed, its iterations, and the error that ended it
// early (empty when it ran to the end).
struct ReplicationResult {
  int replication = 0;
  std::uint64_t seed = 0;
  std::string session_id;
  // Its bearer token: what reads the session afterwards needs it (`relmap-sim dataset
  // --mode physical` exports the samples it learned).
  std::string session_token;
  std::vector<IterationRecord> iterations;
  std::string error;
};

}  // namespace relmap::sim
