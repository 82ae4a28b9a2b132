// relmap-perception: times the perception pipeline on one cloud (one JSON line), renders
// its segmentation, or runs the change detector on two clouds.
//
//   relmap-perception <cloud.pcd | synthetic:WxH> [--voxel 0.008] [--seed 0.05] [--repeat 5]
//       [--png seg.png] [--fpfh shared_voxels|exact_union|raw_points]
//       [--colour corrected|paper2018] [--raw-spacing 0.004]
//       [--raw-normal-radius 0.01] [--no-prevoxelise] [--threads 2]
//       [--fpfh-deviation] [--feature-stats] [--stride 2]
//   relmap-perception --change before.pcd after.pcd --target-point x,y,z
#include <cstdio>
#include <iostream>
#include <string>

#include "change_command.h"
#include "cloud_input.h"
#include "common/command_line.h"
#include "feature_report.h"
#include "perception/colour_histogram.h"
#include "perception/fpfh.h"
#include "pipeline_timing.h"
#include "segmentation_png.h"
#include "timing_options.h"

namespace {

using relmap::tools::PipelineTimings;
using relmap::tools::TimingOptions;

int Fail(const std::string& message) {
  std::cerr << "relmap-perception: " << message << "\n";
  return 1;
}

// The JSON line of a timing run: the cloud, the settings, the median of every stage.
void PrintTimings(const TimingOptions& options, const PipelineTimings& timings,
                  const std::string& extra) {
  namespace rp = relmap::perception;
  using relmap::tools::Median;
  const rp::Frame& last = timings.last;
  const rp::PerceptionConfig& config = options.config;
  // Voxels drive the cost of both stages more than points do (a far table gives one voxel
  // per pixel).
  std::size_t voxels = 0;
  for (const rp::Supervoxel& sv : last.segmentation.supervoxels) voxels += sv.voxels.size();
  std::printf(
      "{\"cloud\":\"%s\",\"stride\":%u,\"points\":%zu,\"valid_points\":%zu,\"voxels\":%zu,"
      "\"supervoxels\":%zu,\"non_finite_rows\":%zu,\"fpfh\":\"%s\",\"colour\":\"%s\","
      "\"raw_spacing\":%g,\"raw_normal_radius\":%g,\"prevoxelise\":%s,\"threads\":%"
      "d,\"repeat\":%d,"
      "\"median_ms\":{\"decode\":%.1f,\"filter\":%.1f,\"supervoxels\":%.1f,\"normals\":%.1f,"
      "\"features\":%.1f,\"total\":%.1f}%s}\n",
      options.input.c_str(), options.stride, last.cloud.size(), last.cloud.valid_points(), voxels,
      last.size(), last.features.non_finite_rows,
      std::string(rp::FpfhSchemeName(config.features.fpfh_scheme)).c_str(),
      std::string(rp::ColourConversionName(config.features.colour)).c_str(),
      static_cast<double>(config.features.raw_point_spacing),
      static_cast<double>(config.features.raw_normal_radius),
      config.supervoxels.prevoxelise ? "true" : "false", config.threads, options.repeat,
      Median(timings.decode), Median(timings.filter), Median(timings.supervoxels),
      Median(timings.normals), Median(timings.features), Median(timings.total), extra.c_str());
}

int Main(int argc, char** argv) {
  namespace tools = relmap::tools;
  if (argc >= 2 && std::string(argv[1]) == "--change") return tools::RunChangeCommand(argc, argv);
  auto options = tools::ParseTimingOptions(argc, argv);
  if (!options.ok()) return Fail(options.status().message());
  auto input = tools::ReadCloudInput(options->input, options->stride);
  if (!input.ok()) return Fail(input.status().message());
  auto timings = tools::TimePipeline(*input, options->config, options->repeat);
  if (!timings.ok()) return Fail(timings.status().message());
  if (!options->png.empty()) {
    if (auto status = relmap::perception::WriteSegmentationPng(timings->last, options->png);
        !status.ok()) {
      return Fail(status.message());
    }
  }
  std::string extra;
  if (options->fpfh_deviation) extra = tools::FpfhDeviationJson(timings->last, options->config);
  if (options->feature_stats) extra += tools::FeatureStatsJson(timings->last.features);
  PrintTimings(*options, *timings, extra);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("relmap-perception", [&] { return Main(argc, argv); });
}
