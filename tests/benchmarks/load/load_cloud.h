// The cloud every session of a run uploads, and the ground truth of its scene
// when there is one.
#pragma once

#include <string>
#include <vector>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::load {

struct LoadCloud {
  v1::Cloud cloud;
  // For the report: "synthetic 320x240" or the PCD file's path.
  std::string description;
  // Per point (row-major): -1 hole, 0 table, k >= 1 the k-th object; empty when
  // the scene has no ground truth (a real capture).
  std::vector<int> object_of_point;
};

// The bytes of a PCD file, sent as they are (Cloud.pcd); the server decodes them.
StatusOr<LoadCloud> ReadPcdCloud(const std::string& path);

}  // namespace relmap::load
