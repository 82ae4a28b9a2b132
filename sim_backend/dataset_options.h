// The settings of one `relmap-sim dataset`: which scene, how many re-spawned frames (or
// physical pushes) from which seed, at what image size, which server, and where the rows go.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "common/status.h"
#include "experiment_options.h"
#include "image_size.h"

namespace relmap::sim {

struct DatasetOptions {
  std::string scene;  // a scene name or a scene file
  // kOracle: every usable supervoxel of re-spawned frames with its ground truth;
  // kPhysical: the targets a physical-mode run pushed, with the labels it learned.
  LabellingMode mode = LabellingMode::kOracle;
  int frames = 20;  // kPhysical: iterations (pushes)
  // The scene's instance and every frame's re-spawn (as `relmap-sim run --mode oracle
  // --seed S` draws them for its first replication).
  std::uint64_t seed = 1;
  std::optional<ImageSize> resolution;  // unset: the scene file's camera
  std::string server;                   // host:port; empty: start one
  std::string server_binary;
  std::string out;         // the labelled CSV (relmap-cmm's format)
  std::string frames_out;  // per row its frame; default out + ".frames"
  std::string truth_out;   // kPhysical: the rows with their ground truth; empty: none
};

// The usage text of `relmap-sim dataset`.
extern const char kDatasetUsage[];

// argv[first..argc) as `--name value` pairs. INVALID_ARGUMENT naming the flag for an
// unknown flag, a missing value, a malformed number or resolution, or a missing
// --scene or --out.
StatusOr<DatasetOptions> ParseDatasetOptions(int argc, const char* const* argv, int first);

}  // namespace relmap::sim
