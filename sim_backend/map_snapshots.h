// The relevance and choice maps of one iteration as PNGs over the simulated camera's
// own frame: DIR/relevance-<r>-<iteration>.png and DIR/choice-<r>-<iteration>.png.
#pragma once

#include <string>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"
#include "simulated_scene.h"

namespace relmap::sim {

// `maps` must carry the point labels of `frame` (ComputeMaps with PointLabels::kInclude).
Status WriteMapSnapshots(const CameraFrame& frame, const v1::ComputeMapsResponse& maps,
                         const std::string& directory, int replication, int iteration);

}  // namespace relmap::sim
