// How an iteration of relmap-robot's loop ended, and the name status.json gives it.
#pragma once

#include <string_view>

namespace relmap::robot {

enum class IterationState {
  kPosted,    // pushed, and the outcome learned
  kSkipped,   // the target lies outside the workspace: not sent to the driver
  kFailed,    // every attempt failed, or the push could not be posted
  kDryRun,    // the target printed instead of pushed
  kNoTarget,  // no supervoxel with usable features
  kStopped,   // by the stop flag, the source's end or max_pushes
};

// "posted", "skipped", "failed", "dry_run", "no_target", "stopped".
constexpr std::string_view IterationStateName(IterationState state) {
  switch (state) {
    case IterationState::kPosted:
      return "posted";
    case IterationState::kSkipped:
      return "skipped";
    case IterationState::kFailed:
      return "failed";
    case IterationState::kDryRun:
      return "dry_run";
    case IterationState::kNoTarget:
      return "no_target";
    case IterationState::kStopped:
      return "stopped";
  }
  return "stopped";
}

}  // namespace relmap::robot
