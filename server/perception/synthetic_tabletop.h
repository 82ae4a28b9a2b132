// common/synthetic_tabletop.h's scene as a decoded Cloud, for the perception tests,
// benchmarks and tool.
#pragma once

#include <cstdint>
#include <vector>

#include "common/synthetic_tabletop.h"
#include "perception/cloud.h"

namespace relmap::perception {

using SyntheticTabletopOptions = synthetic::TabletopOptions;

struct SyntheticTabletop {
  Cloud cloud;
  // Per point: -1 hole (no surface within 3 m), 0 table, k >= 1 the k-th object.
  std::vector<int> object_of_point;
  int objects = 0;
};

SyntheticTabletop MakeSyntheticTabletop(const SyntheticTabletopOptions& options = {});

}  // namespace relmap::perception
