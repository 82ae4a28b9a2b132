// The decode is timed here, the frame's stages by BuildFrame itself.
#include "pipeline_timing.h"

#include <algorithm>
#include <chrono>

namespace relmap::tools {

StatusOr<PipelineTimings> TimePipeline(const CloudInput& input,
                                       const perception::PerceptionConfig& config, int repeat) {
  PipelineTimings timings;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    auto cloud = input.Decode(config.limits);
    if (!cloud.ok()) return cloud.status();
    const double decode_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    auto frame = perception::BuildFrame(*cloud, config);
    if (!frame.ok()) return frame.status();
    timings.decode.push_back(decode_ms);
    timings.filter.push_back(frame->timings.filter_ms);
    timings.supervoxels.push_back(frame->timings.supervoxels_ms);
    timings.normals.push_back(frame->timings.normals_ms);
    timings.features.push_back(frame->timings.features_ms);
    timings.total.push_back(decode_ms + frame->timings.total_ms);
    timings.last = std::move(frame).value();
  }
  return timings;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t m = values.size() / 2;
  return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

}  // namespace relmap::tools
