// Everything a session is configured with, as the layers below take it: one
// struct per layer, their defaults the paper's values.
#pragma once

#include <chrono>
#include <cstddef>

#include "cmm/config.h"
#include "exploration/exploration_config.h"
#include "perception/perception_config.h"

namespace relmap::session {

// The feature dimension of sessions fed with clouds (docs/method.md §2).
inline constexpr int kCloudFeatureDimension = 48;

struct SessionSettings {
  cmm::CmmConfig classifier;
  exploration::ExplorationConfig exploration;
  perception::PerceptionConfig perception;
  int feature_dimension = kCloudFeatureDimension;
};

// What the server decides for every session, whatever its config: how often the model
// is snapshotted and how many frames are kept for PostOutcome.
struct SessionPolicy {
  // With a store: a model snapshot every this many learned samples, so that a restart
  // replays at most that many (0: never).
  std::size_t snapshot_every = 0;
  // With a store: also a snapshot once the samples learned since the last one took
  // this long to learn (0: never), so that a restart relearns about this much
  // whatever the model's size: an update's cost grows with the dataset, so a fixed
  // count of samples to replay does not bound the time of a restore.
  std::chrono::nanoseconds snapshot_after_learning{0};
  // Frames kept for PostOutcome (at least 1); older ones are evicted first.
  std::size_t frame_cache = 8;
};

// Ranges of every layer's settings, checked in one place.
Status Validate(const SessionSettings& settings);

}  // namespace relmap::session
