// Flags with a value read it from the next argument; switches take none.
#include "timing_options.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

#include "perception/colour_histogram.h"
#include "perception/fpfh.h"

namespace relmap::tools {
namespace {

// Sets the option of a flag that takes `value`; false for an unknown flag. Throws
// std::invalid_argument / std::out_of_range for a number that does not parse.
StatusOr<bool> SetValueFlag(const std::string& flag, const std::string& value,
                            TimingOptions& options) {
  perception::PerceptionConfig& config = options.config;
  if (flag == "--voxel") {
    config.supervoxels.voxel_resolution = std::stof(value);
  } else if (flag == "--seed") {
    config.supervoxels.seed_resolution = std::stof(value);
  } else if (flag == "--repeat") {
    options.repeat = std::max(1, std::stoi(value));
  } else if (flag == "--stride") {
    options.stride = static_cast<std::uint32_t>(std::max(1, std::stoi(value)));
  } else if (flag == "--raw-spacing") {
    config.features.raw_point_spacing = std::stof(value);
  } else if (flag == "--raw-normal-radius") {
    config.features.raw_normal_radius = std::stof(value);
  } else if (flag == "--threads") {
    config.threads = std::stoi(value);
  } else if (flag == "--png") {
    options.png = value;
  } else if (flag == "--fpfh") {
    auto scheme = perception::ParseFpfhScheme(value);
    if (!scheme.ok()) return scheme.status();
    config.features.fpfh_scheme = *scheme;
  } else if (flag == "--colour") {
    auto colour = perception::ParseColourConversion(value);
    if (!colour.ok()) return colour.status();
    config.features.colour = *colour;
  } else {
    return false;
  }
  return true;
}

}  // namespace

const char kPerceptionUsage[] =
    "usage: relmap-perception <cloud.pcd | synthetic:WxH> [--voxel m] [--seed m] "
    "[--repeat n] [--png file] [--fpfh shared_voxels|exact_union|raw_points] "
    "[--colour corrected|paper2018] [--raw-spacing m] [--raw-normal-radius m] "
    "[--no-prevoxelise] [--threads n] "
    "[--fpfh-deviation] [--feature-stats] [--stride n]\n"
    "       relmap-perception --change before.pcd after.pcd --target-point x,y,z";

StatusOr<TimingOptions> ParseTimingOptions(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return InvalidArgumentError(kPerceptionUsage);
  TimingOptions options;
  options.input = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--no-prevoxelise") {
      options.config.supervoxels.prevoxelise = false;
    } else if (flag == "--fpfh-deviation") {
      options.fpfh_deviation = true;
    } else if (flag == "--feature-stats") {
      options.feature_stats = true;
    } else {
      if (i + 1 >= argc) return InvalidArgumentError(flag + " needs a value");
      const std::string value = argv[++i];
      StatusOr<bool> known = false;
      try {
        known = SetValueFlag(flag, value, options);
      } catch (const std::exception&) {
        return InvalidArgumentError(fmt::format("bad value '{}' for {}", value, flag));
      }
      if (!known.ok()) return known.status();
      if (!*known) return InvalidArgumentError("unknown option " + flag);
    }
  }
  if (Status status = perception::Validate(options.config); !status.ok()) return status;
  return options;
}

}  // namespace relmap::tools
