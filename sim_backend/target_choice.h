// Which supervoxel of a frame the runner pushes: the server's draw from its choice
// map, or (the baseline of issue 5) a uniform draw over the usable supervoxels.
#pragma once

#include <cstdint>
#include <optional>

#include "common/status.h"
#include "experiment_options.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::sim {

// The index in maps.supervoxels() of the target, or nullopt when the frame has no
// usable supervoxel (nothing can be learned from it). `random_bits` drives the
// uniform draw of TargetSampling::kRandom. INVALID_ARGUMENT when the server's target
// is not among its supervoxels.
StatusOr<std::optional<int>> ChooseTarget(const v1::ComputeMapsResponse& maps,
                                          TargetSampling sampling, std::uint64_t random_bits);

}  // namespace relmap::sim
