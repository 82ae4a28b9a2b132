// The perception pipeline timed stage by stage over repeats of one cloud: decode,
// filter, supervoxels, normals, features.
#pragma once

#include <vector>

#include "cloud_input.h"
#include "common/status.h"
#include "perception/frame.h"
#include "perception/perception_config.h"

namespace relmap::tools {

struct PipelineTimings {
  // Per repeat, milliseconds.
  std::vector<double> decode, filter, supervoxels, normals, features, total;
  perception::Frame last;  // the frame of the last repeat
};

// `repeat` (>= 1) decodes and frames of `input`; the first error ends them.
StatusOr<PipelineTimings> TimePipeline(const CloudInput& input,
                                       const perception::PerceptionConfig& config, int repeat);

// The median of `values` (not empty); the mean of the middle two for an even count.
double Median(std::vector<double> values);

}  // namespace relmap::tools
