// Flag parsing and the usage text, side by side so that they agree.
#include "experiment_options.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "flags.h"

namespace relmap::sim {
namespace {

constexpr std::string_view kRunFlags[] = {"scene",         "mode",
                                          "iterations",    "replications",
                                          "seed",          "server",
                                          "server-binary", "out",
                                          "variant",       "alpha",
                                          "sampling",      "parallel",
                                          "snapshots",     "change-min-neighbours",
                                          "resolution",    "change-method",
                                          "labels",        "novelty",
                                          "random-share",  "class-balanced"};

// "1,10,100": iterations in [1, iterations], sorted, without repeats.
StatusOr<std::vector<int>> SnapshotList(const std::string& text, int iterations) {
  std::vector<int> snapshots;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    StatusOr<long long> iteration =
        ParseInteger("snapshots", text.substr(start, comma - start), 1, iterations);
    if (!iteration.ok()) return iteration.status();
    snapshots.push_back(static_cast<int>(*iteration));
    start = comma + 1;
  }
  std::sort(snapshots.begin(), snapshots.end());
  snapshots.erase(std::unique(snapshots.begin(), snapshots.end()), snapshots.end());
  return snapshots;
}

// The words of a flag that names one of N choices (two unless said); parsing and naming
// read the same table.
template <typename Enum, std::size_t N = 2>
using Words = std::array<std::pair<Enum, const char*>, N>;
constexpr Words<LabellingMode> kModes = {
    {{LabellingMode::kOracle, "oracle"}, {LabellingMode::kPhysical, "physical"}}};
constexpr Words<TargetSampling> kSamplings = {
    {{TargetSampling::kChoice, "choice"}, {TargetSampling::kRandom, "random"}}};
constexpr Words<LabelScope, 4> kLabelScopes = {{{LabelScope::kTarget, "target"},
                                                {LabelScope::kObject, "object"},
                                                {LabelScope::kMoved, "moved"},
                                                {LabelScope::kNear, "near"}}};
constexpr Words<bool> kOnOff = {{{true, "on"}, {false, "off"}}};
constexpr Words<v1::ChangeMethod> kChangeMethods = {
    {{v1::CHANGE_METHOD_VISIBILITY, "visibility"}, {v1::CHANGE_METHOD_PAPER2018, "paper2018"}}};
constexpr Words<v1::ClassifierVariant, 3> kVariants = {
    {{v1::CLASSIFIER_VARIANT_CORRECTED, "corrected"},
     {v1::CLASSIFIER_VARIANT_CORRECTED_V1, "corrected_v1"},
     {v1::CLASSIFIER_VARIANT_PAPER2018, "paper2018"}}};

// `*text`, if given, as one of `words` into `*out`.
template <typename Enum, std::size_t N>
Status ParseWord(std::string_view flag, const std::string* text, const Words<Enum, N>& words,
                 Enum* out) {
  if (text == nullptr) return OkStatus();
  std::string choices;
  for (const auto& [value, word] : words) {
    if (*text == word) {
      *out = value;
      return OkStatus();
    }
    choices += (choices.empty() ? "" : " | ") + std::string(word);
  }
  return FlagError(flag, "is " + choices + ", got '" + *text + "'");
}

template <typename Enum, std::size_t N>
const char* WordOf(const Words<Enum, N>& words, Enum value) {
  for (const auto& [candidate, word] : words) {
    if (candidate == value) return word;
  }
  return "unspecified";
}

// 1, 10, 100, ... below `iterations`, then `iterations` itself.
std::vector<int> DefaultSnapshots(int iterations) {
  std::vector<int> snapshots;
  for (long long i = 1; i < iterations; i *= 10) snapshots.push_back(static_cast<int>(i));
  snapshots.push_back(iterations);
  return snapshots;
}

}  // namespace

const char kRunUsage[] =
    "usage: relmap-sim run --scene <name|file> --out DIR [--mode oracle|physical]\n"
    "                      [--iterations 100] [--replications 1] [--seed 1]\n"
    "                      [--server host:port | --server-binary PATH]\n"
    "                      [--variant corrected|corrected_v1|paper2018] [--alpha A]\n"
    "                      [--sampling choice|random] [--parallel 2]\n"
    "                      [--snapshots 1,10,100|none] [--change-min-neighbours N]\n"
    "                      [--resolution WxH] [--change-method visibility|paper2018]\n"
    "                      [--labels target|object|moved|near] [--novelty on|off]\n"
    "                      [--random-share E] [--class-balanced on|off]\n"
    "  --mode        oracle: every object re-spawned each iteration, the target labelled\n"
    "                with its ground truth (the paper's simplified setup); physical: the\n"
    "                push happens and the server's change detector labels it\n"
    "  --seed        replication r uses seed + r for its session, scene and draws\n"
    "  --server      a running relmap-server; without it relmap-sim starts its own on\n"
    "                127.0.0.1 (port 0) with a temporary data directory, from\n"
    "                --server-binary, else relmap-server next to relmap-sim, else the build's\n"
    "  --alpha       the tolerance-ellipsoid significance level (default: the server's 0.25)\n"
    "  --sampling    choice: the server's draw from its choice map; random: uniform over\n"
    "                the usable supervoxels\n"
    "  --labels      target: the pushed supervoxel alone (default, the paper's protocol);\n"
    "                object: also the rest of its object: in oracle mode the target's\n"
    "                whole body with its label, as PostOutcomeRequest.object_supervoxels; in\n"
    "                physical mode what the change detector saw move with the target\n"
    "                (ChangeDetectorConfig.learn_moved_object);\n"
    "                moved: the rest of the object only when the push moves it: in oracle\n"
    "                mode the body of a moveable target, in physical mode as object;\n"
    "                near: as moved, and of a still body the 8 supervoxels nearest the\n"
    "                target (oracle mode)\n"
    "  --novelty     the session's choice map weighs supervoxels by their novelty\n"
    "  --random-share  the share of the choice map drawn uniformly, in [0, 1] (0)\n"
    "  --class-balanced  on: the session draws half its pushes among what it thinks\n"
    "                moveable and half among the rest (ExplorationConfig.class_balanced);\n"
    "                default: the server's\n"
    "  --parallel    replications run at once, each its own session (default 2)\n"
    "  --snapshots   iterations whose relevance and choice maps are saved as PNGs\n"
    "                (default 1, 10, 100, ... and the last)\n"
    "  --change-method  physical mode: how the server labels a push (default visibility;\n"
    "                paper2018: the authors' octree difference and ICP)\n"
    "  --change-min-neighbours  paper2018: the change detector's radius filter keeps\n"
    "                points with this many neighbours in 1 cm (default 20 scaled by the\n"
    "                camera's point density against a 640x480 Kinect)\n"
    "  --resolution  the camera's size, its field of view kept (default: the scene's;\n"
    "                640x480 is the paper's Kinect)\n"
    "Writes DIR/replication-<r>.csv, DIR/summary.json, DIR/{accuracy,precision,recall,\n"
    "samples,components}.png and DIR/{relevance,choice}-<r>-<iteration>.png.\n"
    "Exit codes: 0 success, 1 a failed run or server error, 2 bad arguments or files.\n";

StatusOr<ExperimentOptions> ParseExperimentOptions(int argc, const char* const* argv, int first) {
  StatusOr<FlagValues> flags = ParseFlagPairs(argc, argv, first, kRunFlags);
  if (!flags.ok()) return flags.status();
  const auto value = [&](std::string_view name) { return FlagValue(*flags, name); };

  ExperimentOptions options;
  if (Status required = RequireFlags(*flags, {"scene", "out"}); !required.ok()) return required;
  options.scene = *value("scene");
  options.out = *value("out");
  if (Status parsed = ParseWord("mode", value("mode"), kModes, &options.mode); !parsed.ok()) {
    return parsed;
  }
  const std::pair<std::string_view, int*> counts[] = {{"iterations", &options.iterations},
                                                      {"replications", &options.replications},
                                                      {"parallel", &options.parallel}};
  for (const auto& [name, field] : counts) {
    if (const std::string* text = value(name)) {
      StatusOr<long long> count = ParseInteger(name, *text, 1, 1000000);
      if (!count.ok()) return count.status();
      *field = static_cast<int>(*count);
    }
  }
  if (const std::string* seed = value("seed")) {
    StatusOr<std::uint64_t> parsed = ParseUnsigned("seed", *seed);
    if (!parsed.ok()) return parsed.status();
    options.seed = *parsed;
  }
  if (Status read = ReadServerFlags(*flags, &options.server, &options.server_binary); !read.ok()) {
    return read;
  }
  if (const std::string* alpha = value("alpha")) {
    StatusOr<double> parsed = ParseUnitInterval("alpha", *alpha);
    if (!parsed.ok()) return parsed.status();
    options.alpha = *parsed;
  }
  if (const std::string* neighbours = value("change-min-neighbours")) {
    char* end = nullptr;
    const long parsed = std::strtol(neighbours->c_str(), &end, 10);
    if (neighbours->empty() || *end != '\0' || parsed < 1 || parsed > 1000) {
      return FlagError("change-min-neighbours",
                       "expects an integer in [1, 1000], got '" + *neighbours + "'");
    }
    options.change_min_neighbours = static_cast<int>(parsed);
  }
  if (const std::string* resolution = value("resolution")) {
    StatusOr<ImageSize> parsed = ParseResolution(*resolution);
    if (!parsed.ok()) return parsed.status();
    options.resolution = *parsed;
  }
  // The word flags, each checked against its list; the first bad one is reported.
  for (const Status& parsed :
       {ParseWord("variant", value("variant"), kVariants, &options.variant),
        ParseWord("change-method", value("change-method"), kChangeMethods, &options.change_method),
        ParseWord("sampling", value("sampling"), kSamplings, &options.sampling),
        ParseWord("labels", value("labels"), kLabelScopes, &options.labels),
        ParseWord("novelty", value("novelty"), kOnOff, &options.novelty)}) {
    if (!parsed.ok()) return parsed;
  }
  if (const std::string* balanced = value("class-balanced")) {
    bool on = false;
    if (Status parsed = ParseWord("class-balanced", balanced, kOnOff, &on); !parsed.ok()) {
      return parsed;
    }
    options.class_balanced = on;
  }
  if (const std::string* share = value("random-share")) {
    StatusOr<double> parsed = ParseUnitInterval("random-share", *share);
    if (!parsed.ok()) return parsed.status();
    options.random_share = *parsed;
  }
  if (const std::string* snapshots = value("snapshots"); snapshots && *snapshots == "none") {
    options.snapshots.clear();
  } else if (snapshots) {
    StatusOr<std::vector<int>> parsed = SnapshotList(*snapshots, options.iterations);
    if (!parsed.ok()) return parsed.status();
    options.snapshots = *parsed;
  } else {
    options.snapshots = DefaultSnapshots(options.iterations);
  }
  return options;
}

const char* ModeName(LabellingMode mode) { return WordOf(kModes, mode); }

const char* SamplingName(TargetSampling sampling) { return WordOf(kSamplings, sampling); }

const char* LabelScopeName(LabelScope labels) { return WordOf(kLabelScopes, labels); }

const char* VariantName(v1::ClassifierVariant variant) { return WordOf(kVariants, variant); }

const char* ChangeMethodName(v1::ChangeMethod method) { return WordOf(kChangeMethods, method); }

}  // namespace relmap::sim
