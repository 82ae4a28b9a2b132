// relmap-perception's flags for timing the pipeline on one cloud.
#pragma once

#include <cstdint>
#include <string>

#include "common/status.h"
#include "perception/perception_config.h"

namespace relmap::tools {

struct TimingOptions {
  std::string input;  // a PCD file or "synthetic:WxH"
  perception::PerceptionConfig config;
  int repeat = 5;
  std::uint32_t stride = 1;  // every stride-th row and column of an organized cloud
  std::string png;           // where to render the segmentation, if anywhere
  bool fpfh_deviation = false;
  bool feature_stats = false;
};

// The usage line of both commands, for the error that shows it.
extern const char kPerceptionUsage[];

// The options of `relmap-perception <input> [flags]`, validated; INVALID_ARGUMENT
// naming the flag or value that is wrong.
StatusOr<TimingOptions> ParseTimingOptions(int argc, char** argv);

}  // namespace relmap::tools
