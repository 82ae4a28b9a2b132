// Which other supervoxels of a pushed target's body an oracle outcome names
// (PostOutcomeRequest.object_supervoxels), for each --labels scope (docs/method.md §4.5).
#pragma once

#include <cstdint>
#include <vector>

#include "experiment_options.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::sim {

// How many of a still body's supervoxels --labels near names: the target's ring on a
// surface (VCCS seeds on a grid have eight neighbours there), what a pusher touching the
// target could have felt. Not fitted to any scene.
inline constexpr std::size_t kNearSupervoxels = 8;

// Of `body` (indices into maps.supervoxels of the target's body, the target excluded),
// the ids that `scope` posts beside supervoxel `index` of `maps`, whose truth is `moveable`:
// none (target), all (object), all when moveable (moved), and for near all when moveable
// and else the kNearSupervoxels whose centroids lie nearest the target's, nearest first
// (ties by id). All of them come in the body's order.
std::vector<std::uint32_t> BodyLabels(LabelScope scope, bool moveable,
                                      const v1::ComputeMapsResponse& maps, int index,
                                      const std::vector<int>& body);

}  // namespace relmap::sim
