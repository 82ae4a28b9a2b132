// One frame of a `relmap-sim dataset`: the scene re-spawned, captured, segmented and
// described by the server, and each usable supervoxel labelled with the ground truth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/status.h"
#include "relevance_client.h"
#include "simulated_scene.h"

namespace relmap::sim {

// A labelled sample: a supervoxel's feature as the server computes it.
struct DatasetRow {
  int frame = 0;
  bool moveable = false;  // ground_truth.h: >= 50 % of its points on a moveable body
  // The body that >= 50 % of its points hit, or kNoBody (ground_truth.h): the rows of one
  // frame with the same body show one object, which a push moves as a whole.
  std::int32_t body = kNoBody;
  // The object the server sees it on (Supervoxel.object): what a push would move with it,
  // as far as the frame's geometry tells.
  std::uint32_t object = 0;
  std::vector<double> features;
};

struct LabelledFrame {
  std::vector<DatasetRow> rows;  // in the server's supervoxel order
  // Supervoxels left out because a feature value is not finite (too few points or
  // neighbours for a histogram): the classifier never sees them either.
  std::size_t non_finite = 0;
  double server_ms = 0;  // ComputeMaps inside the server
};

// Frame `frame` (1-based): `scene` re-spawned with the seed `relmap-sim run --mode
// oracle` uses at that iteration of the replication seeded `seed`, then ComputeMaps on
// `session` with the features and point labels. The session learns nothing.
// The call's status, or ground_truth.h's INVALID_ARGUMENT, on failure.
StatusOr<LabelledFrame> LabelFrame(SimulatedScene& scene, client::RelevanceClient& client,
                                   const client::SessionHandle& session, std::uint64_t seed,
                                   int frame);

}  // namespace relmap::sim
