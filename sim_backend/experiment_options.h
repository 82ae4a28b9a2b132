// The settings of one `relmap-sim run`: which scene, how it is labelled, how many
// iterations and replications, which server and classifier, where the results go.
// Parsed and checked in one place.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/status.h"
#include "image_size.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::sim {

// How the outcome of a push is labelled (issue 5, docs/method.md §7).
enum class LabellingMode {
  // The paper's simplified setup: every object re-spawned each iteration, the chosen
  // supervoxel labelled with its ground truth; nothing is pushed.
  kOracle,
  // The scene persists, the push happens, and the server's change detector labels it
  // from the before and after clouds.
  kPhysical,
};

// Where the target comes from.
enum class TargetSampling {
  kChoice,  // the server's draw from its choice map (§4.3)
  kRandom,  // a uniform draw over the usable supervoxels, with the runner's seeded RNG
};

// What a push labels.
enum class LabelScope {
  kTarget,  // the target alone (the paper's protocol)
  // Oracle: every other supervoxel of the target's body, with its label
  // (object_supervoxels);
  // physical: the target and what the change detector saw move with it
  // (ChangeDetectorConfig.learn_moved_object).
  kObject,
  // Oracle: the target, and every other supervoxel of its body when it is moveable: what a
  // camera sees move with a push. A body that did not move shows nothing of its extent, and
  // a support surface is hundreds of supervoxels (docs/method.md §4.5).
  // physical: as kObject.
  kMoved,
  // Oracle: the body of a moveable target, and of a still one the few supervoxels nearest
  // the target (body_labels.h): bounded however large the still body.
  // physical: as kObject.
  kNear,
};

struct ExperimentOptions {
  std::string scene;  // a scene name or a scene file
  LabellingMode mode = LabellingMode::kOracle;
  int iterations = 100;
  int replications = 1;
  // Replication r uses seed + r for its session and its scene.
  std::uint64_t seed = 1;
  // host:port of a running server; empty: start one (server_launcher.h).
  std::string server;
  // The relmap-server to start; empty: the one next to relmap-sim, else the build's.
  std::string server_binary;
  std::string out;  // the output directory, created if missing
  v1::ClassifierVariant variant = v1::CLASSIFIER_VARIANT_CORRECTED;
  std::optional<double> alpha;  // unset: the server's default (0.25)
  TargetSampling sampling = TargetSampling::kChoice;
  LabelScope labels = LabelScope::kTarget;
  // The session's exploration (SessionConfig.exploration); unset: the server's default.
  bool novelty = false;
  std::optional<double> random_share;
  std::optional<bool> class_balanced;
  // Physical mode: the change detector's radius filter keeps points with at least this
  // many neighbours within 1 cm (docs/method.md §5, 20 for a 640×480 Kinect). Unset: 20
  // scaled by the camera's point density, (width / 640)², at least 3.
  std::optional<int> change_min_neighbours;
  // Physical mode: how the server labels a push.
  v1::ChangeMethod change_method = v1::CHANGE_METHOD_VISIBILITY;
  std::optional<ImageSize> resolution;  // unset: the scene file's camera
  // Replications running at once, each its own session on its own thread.
  int parallel = 2;
  // Iterations (1-based) whose relevance and choice maps are saved as PNGs.
  std::vector<int> snapshots;
};

// The usage text of `relmap-sim run`.
extern const char kRunUsage[];

// argv[first..argc) as `--name value` pairs. INVALID_ARGUMENT naming the flag for an
// unknown flag, a missing value, a malformed or out-of-range number, or a missing
// --scene or --out. Without --snapshots: 1, 10, 100, ... up to and with the last
// iteration.
StatusOr<ExperimentOptions> ParseExperimentOptions(int argc, const char* const* argv, int first);

// The names the summary uses for the enums.
const char* ModeName(LabellingMode mode);
const char* SamplingName(TargetSampling sampling);
const char* LabelScopeName(LabelScope labels);
const char* VariantName(v1::ClassifierVariant variant);
const char* ChangeMethodName(v1::ChangeMethod method);

}  // namespace relmap::sim
