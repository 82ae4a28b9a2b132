// Flag parsing and the usage text of `relmap-sim dataset`, side by side.
#include "dataset_options.h"

#include <string_view>

#include "flags.h"

namespace relmap::sim {
namespace {

constexpr std::string_view kDatasetFlags[] = {"scene",  "frames",   "seed",          "resolution",
                                              "server", "out",      "server-binary", "frames-out",
                                              "mode",   "truth-out"};

}  // namespace

const char kDatasetUsage[] =
    "usage: relmap-sim dataset --scene <name|file> --out FILE.csv [--frames 20] [--seed 1]\n"
    "                          [--mode oracle|physical] [--truth-out FILE]\n"
    "                          [--resolution WxH] [--frames-out FILE]\n"
    "                          [--server host:port | --server-binary PATH]\n"
    "  Re-spawns every object of the scene --frames times (the paper's simplified setup,\n"
    "  the frames of `relmap-sim run --mode oracle --seed S`), has the server segment and\n"
    "  describe each frame (ComputeMaps with include_features) and labels every usable\n"
    "  supervoxel with the simulator's ground truth (1: >= 50 % of its points on a\n"
    "  moveable body, 0: background).\n"
    "  --mode        oracle: the above (default); physical: what a physical-mode run\n"
    "                learned instead: `relmap-sim run --mode physical --seed S` for\n"
    "                --frames pushes, then per pushed target the feature its session\n"
    "                learned and the change detector's label (its label noise)\n"
    "  --out         rows 'label,f1,...,f48' under a header line, as relmap-cmm and\n"
    "                relmap-bench-learning read them; the same seed gives the same bytes\n"
    "  --frames-out  per row of --out, in the same order, its frame (1..N), the body\n"
    "                >= 50 % of its points hit (-1: none) and the object the server sees\n"
    "                it on (Supervoxel.object) under a header 'frame,body,object'\n"
    "                (default: FILE.csv.frames); physical: per row its iteration, the\n"
    "                pushed supervoxel, the learned label and the ground truth under\n"
    "                'iteration,target,label,truth'\n"
    "  --truth-out   physical: the rows of --out again, labelled with the ground truth\n"
    "  --resolution  the camera's size, its field of view kept (default: the scene's)\n"
    "  --server      as for `relmap-sim run`: without it relmap-sim starts its own server\n"
    "Supervoxels with a non-finite feature value are left out and counted on stderr.\n"
    "Exit codes: 0 success, 1 a failed run or server error, 2 bad arguments or files.\n";

StatusOr<DatasetOptions> ParseDatasetOptions(int argc, const char* const* argv, int first) {
  StatusOr<FlagValues> flags = ParseFlagPairs(argc, argv, first, kDatasetFlags);
  if (!flags.ok()) return flags.status();
  const auto value = [&](std::string_view name) { return FlagValue(*flags, name); };

  DatasetOptions options;
  if (Status required = RequireFlags(*flags, {"scene", "out"}); !required.ok()) return required;
  options.scene = *value("scene");
  options.out = *value("out");
  options.frames_out = value("frames-out") ? *value("frames-out") : options.out + ".frames";
  if (options.frames_out == options.out) {
    return FlagError("frames-out", "must not be the --out file");
  }
  if (const std::string* mode = value("mode")) {
    if (*mode == "physical") {
      options.mode = LabellingMode::kPhysical;
    } else if (*mode != "oracle") {
      return FlagError("mode", "expects oracle or physical, got '" + *mode + "'");
    }
  }
  if (const std::string* truth = value("truth-out")) {
    if (options.mode != LabellingMode::kPhysical) {
      return FlagError("truth-out", "needs --mode physical (oracle rows are the truth)");
    }
    if (*truth == options.out || *truth == options.frames_out) {
      return FlagError("truth-out", "must be another file than --out and --frames-out");
    }
    options.truth_out = *truth;
  }
  if (const std::string* frames = value("frames")) {
    StatusOr<long long> count = ParseInteger("frames", *frames, 1, 1000000);
    if (!count.ok()) return count.status();
    options.frames = static_cast<int>(*count);
  }
  if (const std::string* seed = value("seed")) {
    StatusOr<std::uint64_t> parsed = ParseUnsigned("seed", *seed);
    if (!parsed.ok()) return parsed.status();
    options.seed = *parsed;
  }
  if (const std::string* resolution = value("resolution")) {
    StatusOr<ImageSize> parsed = ParseResolution(*resolution);
    if (!parsed.ok()) return parsed.status();
    options.resolution = *parsed;
  }
  if (Status read = ReadServerFlags(*flags, &options.server, &options.server_binary); !read.ok()) {
    return read;
  }
  return options;
}

}  // namespace relmap::sim
