// The synthetic tabletop of the perception layer as a load cloud, with the object
// of every point as ground truth. Built only with RELMAP_WITH_PERCEPTION.
#pragma once

#include <cstdint>

#include "load_cloud.h"

namespace relmap::load {

// The tabletop (seed 1) at `width`×`height` in the packed layout of the API.
LoadCloud MakeSyntheticCloud(std::uint32_t width, std::uint32_t height);

}  // namespace relmap::load
