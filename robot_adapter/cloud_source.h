// Where relmap-robot's clouds come from: a camera, a directory of recorded frames, the
// simulator. One interface, so the exploration loop does not care which.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::robot {

// One captured cloud, and what the source knows of the truth.
struct SourceFrame {
  v1::Cloud cloud;
  // Sources that know which points are on moveable objects (the simulator) set this:
  // per supervoxel of `maps` (computed from `cloud` with point labels), whether it is
  // part of a moveable object.
  std::function<StatusOr<std::vector<bool>>(const v1::ComputeMapsResponse& maps)> truth;
};

class CloudSource {
 public:
  virtual ~CloudSource() = default;
  // The next cloud; nullopt when the source has ended (no more files). Errors for
  // unreadable input.
  virtual StatusOr<std::optional<SourceFrame>> Next() = 0;
};

}  // namespace relmap::robot
