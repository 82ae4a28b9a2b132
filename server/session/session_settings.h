// Everything a session is configured with, as the layers below take it: one
// struct per layer, their defaults the paper's values.
#pragma once

#include <cstddef>

#include "cmm/config.h"
#include "exploration/exploration_config.h"
#include "perception/perception_config.h"

namespace relmap::session {

// The feature dimension of sessions fed with clouds (ALGORITHMS §2).
inline constexpr int kCloudFeatureDimension = 48;

struct SessionSettings {
  cmm::CmmConfig classifier;
  exploration::ExplorationConfig exploration;
  perception::PerceptionConfig perception;
  int feature_dimension = kCloudFeatureDimension;
  // Frames kept for PostOutcome; older ones are evicted first.
  std::size_t frame_cache = 8;
};

// Ranges of every layer's settings, checked in one place.
Status Validate(const SessionSettings& settings);

}  // namespace relmap::session
