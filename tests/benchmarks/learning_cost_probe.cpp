// The classifier's learning cost as the dataset grows (docs/reliability.md,
// "Learning cost"): CPU time per IAGMM update in the window of samples before
// each checkpoint n, the candidate models evaluated per update, and the time to
// restore the model at n as a server does (its latest snapshot, then the samples
// after it relearned) under the two snapshot policies of SessionPolicy. Streams:
// uniform random 48-d vectors with fair random labels (data that does not
// cluster), the learning benchmark's built-in streams (structured 48-d data)
// and labelled CSV files (e.g. a relmap-sim dataset, learned in row order):
//   build/tests/benchmarks/learning_cost_probe --streams random48,xor48-unit-range
//   build/tests/benchmarks/learning_cost_probe --streams /tmp/wb.csv --restore off
// CPU time of this thread, not wall time: the figure does not depend on what
// else runs on the machine.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "common/command_line.h"
#include "common/labelled_csv.h"
#include "common/random.h"
#include "learning_bench/streams.h"

namespace relmap::cmm {
namespace {

constexpr int kDimension = 48;
constexpr std::string_view kUsage =
    "usage: learning_cost_probe [--streams random48,xor48,...] [--checkpoints 250,1000,2000,5000]\n"
    "                           [--window 250] [--variant corrected] [--seed 1]\n"
    "                           [--restore on|off]\n"
    "  random48: uniform [0,1)^48 with fair random labels; a name ending in .csv:\n"
    "  that file (label,f1,...,fp rows, learned in row order); other names: the\n"
    "  learning benchmark's built-in streams (relmap-bench-learning --help).\n"
    "  --restore off: skip the restore timings (the update figures only).\n";

struct Options {
  std::vector<std::string> streams{"random48", "xor48-unit-range", "rings48"};
  std::vector<int> checkpoints{250, 1000, 2000, 5000};
  int window = 250;
  Variant variant = Variant::kCorrected;
  std::uint64_t seed = 1;
  bool restore = true;
};

[[noreturn]] void Fail(const std::string& message) {
  tools::ExitWithError("learning_cost_probe", message);
}

std::vector<std::string> SplitList(std::string_view text) {
  std::vector<std::string> out;
  while (!text.empty()) {
    const auto comma = text.find(',');
    out.emplace_back(text.substr(0, comma));
    text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
  }
  return out;
}

Options ParseArguments(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      std::exit(0);
    }
    if (i + 1 >= argc) Fail(fmt::format("{} needs a value\n{}", flag, kUsage));
    const char* value = argv[++i];
    const auto number = [&] {
      return tools::ParseNumberOrExit("learning_cost_probe", flag, value);
    };
    if (flag == "--streams") {
      options.streams = SplitList(value);
    } else if (flag == "--checkpoints") {
      options.checkpoints.clear();
      for (const std::string& n : SplitList(value)) {
        options.checkpoints.push_back(
            static_cast<int>(tools::ParseNumberOrExit("learning_cost_probe", flag, n.c_str())));
      }
      std::sort(options.checkpoints.begin(), options.checkpoints.end());
    } else if (flag == "--window") {
      options.window = static_cast<int>(number());
    } else if (flag == "--variant") {
      const auto variant = ParseVariant(value);
      if (!variant.ok()) Fail(variant.status().message());
      options.variant = *variant;
    } else if (flag == "--seed") {
      options.seed = static_cast<std::uint64_t>(number());
    } else if (flag == "--restore") {
      if (std::string_view(value) != "on" && std::string_view(value) != "off") {
        Fail(fmt::format("--restore takes on or off\n{}", kUsage));
      }
      options.restore = std::string_view(value) == "on";
    } else {
      Fail(fmt::format("unknown argument '{}'\n{}", flag, kUsage));
    }
  }
  if (options.checkpoints.empty() || options.checkpoints.front() < options.window ||
      options.window < 1) {
    Fail("checkpoints must be at least the window, and the window at least 1");
  }
  return options;
}

double ThreadCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

datasets::LabelledSamples RandomVectors(int count, std::uint64_t seed) {
  Random random(seed);
  datasets::LabelledSamples out;
  out.features.resize(count, kDimension);
  out.labels.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    for (int d = 0; d < kDimension; ++d) out.features(i, d) = random.UniformUnit();
    out.labels[static_cast<std::size_t>(i)] = static_cast<int>(random.UniformIndex(2));
  }
  return out;
}

datasets::LabelledSamples MakeSamples(const std::string& name, int count, std::uint64_t seed) {
  if (name == "random48") return RandomVectors(count, seed);
  if (name.ends_with(".csv")) {
    auto file = datasets::ReadLabelledCsv(name);
    if (!file.ok()) Fail(file.status().message());
    if (file->features.rows() < count) {
      Fail(fmt::format("{} has {} samples, the last checkpoint needs {}", name,
                       file->features.rows(), count));
    }
    return *std::move(file);
  }
  const learning_bench::StreamSpec* spec = learning_bench::FindBuiltInStream(name);
  if (spec == nullptr) Fail(fmt::format("unknown stream '{}'\n{}", name, kUsage));
  return learning_bench::MakeStream(*spec, {.train = count, .test = 1}, seed, 0).train;
}

// A snapshot as a session stores it: the model after its first `count` samples.
struct StoredModel {
  CmmSnapshot snapshot;
  int count = 0;
};

// CPU ms to bring a stored session back as the server does (session_restore.cpp):
// the model from its snapshot, then the samples after it relearned.
double RestoreMilliseconds(const StoredModel& stored, const datasets::LabelledSamples& samples,
                           int count) {
  const double start = ThreadCpuMilliseconds();
  auto restored = CollaborativeMixtureModels::Restore(stored.snapshot);
  if (!restored.ok()) Fail(restored.status().message());
  for (int i = stored.count; i < count; ++i) {
    (void)restored->Add(samples.features.row(i).transpose(),
                        samples.labels[static_cast<std::size_t>(i)]);
  }
  return ThreadCpuMilliseconds() - start;
}

void Probe(const std::string& name, const Options& options) {
  const int total = options.checkpoints.back();
  const datasets::LabelledSamples samples = MakeSamples(name, total, options.seed);
  auto model = CollaborativeMixtureModels::Create(CmmConfig::ForVariant(options.variant),
                                                  static_cast<int>(samples.features.cols()));
  if (!model.ok()) Fail(model.status().message());

  std::vector<double> update_ms;
  std::vector<int> candidates;
  update_ms.reserve(static_cast<std::size_t>(total));
  candidates.reserve(static_cast<std::size_t>(total));
  // The two snapshot policies of a server (SessionPolicy): every 500 samples, at
  // its worst 499 samples before the checkpoint; and after 0.5 s of learning.
  constexpr int kSnapshotEvery = 500;
  constexpr double kSnapshotAfterMs = 500.0;
  std::map<int, StoredModel> every_worst;  // per checkpoint
  StoredModel after_learning{model->Snapshot(), 0};
  double learning_since_snapshot_ms = 0.0;
  std::size_t next_checkpoint = 0;
  for (int i = 0; i < total; ++i) {
    for (const int c : options.checkpoints) {
      if (i == std::max(0, c - (kSnapshotEvery - 1))) every_worst[c] = {model->Snapshot(), i};
    }
    const int checkpoint = options.checkpoints[next_checkpoint];
    const double start = ThreadCpuMilliseconds();
    const auto report = model->Add(samples.features.row(i).transpose(),
                                   samples.labels[static_cast<std::size_t>(i)]);
    update_ms.push_back(ThreadCpuMilliseconds() - start);
    if (!report.ok()) Fail(report.status().message());
    candidates.push_back(report->candidates_evaluated);
    learning_since_snapshot_ms += update_ms.back();
    if (learning_since_snapshot_ms >= kSnapshotAfterMs) {
      after_learning = {model->Snapshot(), i + 1};
      learning_since_snapshot_ms = 0.0;
    }
    if (i + 1 != checkpoint) continue;
    ++next_checkpoint;

    const auto first = update_ms.end() - options.window;
    std::vector<double> window(first, update_ms.end());
    std::sort(window.begin(), window.end());
    double window_total = 0.0;
    for (double ms : window) window_total += ms;
    const auto candidates_first = candidates.end() - options.window;
    double candidates_total = 0.0;
    for (auto it = candidates_first; it != candidates.end(); ++it) candidates_total += *it;
    const int candidates_max = *std::max_element(candidates_first, candidates.end());

    fmt::print(
        "{:<18} n={:<5} K={:>2}+{:<3} L={:<12.6g} update ms: mean {:6.3f} p50 {:6.3f} p99 {:7.3f} "
        "max {:7.3f} | candidates: mean {:5.2f} max {:2}",
        std::filesystem::path(name).filename().string(), i + 1, model->component_count(0),
        model->component_count(1), model->LogLikelihood(), window_total / options.window,
        window[window.size() / 2],
        window[static_cast<std::size_t>(0.99 * static_cast<double>(window.size() - 1))],
        window.back(), candidates_total / options.window, candidates_max);
    if (options.restore) {
      fmt::print(
          " | restore ms: snapshot of n {:6.1f}, every 500 (worst, +{} samples) {:8.1f}, after "
          "0.5 s (+{}) {:7.1f}",
          RestoreMilliseconds({model->Snapshot(), i + 1}, samples, i + 1),
          i + 1 - every_worst[checkpoint].count,
          RestoreMilliseconds(every_worst[checkpoint], samples, i + 1),
          i + 1 - after_learning.count, RestoreMilliseconds(after_learning, samples, i + 1));
    }
    fmt::print("\n");
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace relmap::cmm

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("learning_cost_probe", [&] {
    const relmap::cmm::Options options = relmap::cmm::ParseArguments(argc, argv);
    fmt::print("variant {}, window {} samples before each n, CPU time of one thread\n",
               relmap::cmm::VariantName(options.variant), options.window);
    for (const std::string& stream : options.streams) relmap::cmm::Probe(stream, options);
    return 0;
  });
}
