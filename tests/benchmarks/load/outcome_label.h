// The label relmap-load posts for a pushed target, derived deterministically so
// that a run is reproducible from --seed.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "relmap/v1/relevance_service.pb.h"

namespace relmap::load {

// The synthetic scene's ground truth: the object that most of the target's points
// belong to (ComputeMaps' point_labels give each point's supervoxel). An object
// (id >= 1) moves when pushed; the table (0) does not. nullopt when point_labels
// does not have one entry per point of the scene.
std::optional<v1::Label> GroundTruthLabel(const v1::ComputeMapsResponse& maps,
                                          const std::vector<int>& object_of_point);

// For a real capture, which has no ground truth: a fair coin drawn from the
// session's seed and the cycle number, so the same run posts the same labels
// however its calls interleave or are retried.
v1::Label CoinLabel(std::uint64_t session_seed, std::uint64_t cycle);

}  // namespace relmap::load
