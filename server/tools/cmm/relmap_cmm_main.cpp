// relmap-cmm: the classifier on its own, for researchers and side-by-side
// comparisons. Trains online on a CSV stream (or lets the choice map pick from
// it, --active), then prints one JSON object with the model, test scores and
// latencies.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "cmm/config_spec.h"
#include "cmm/log_math.h"
#include "common/command_line.h"
#include "common/labelled_csv.h"
#include "common/metrics.h"
#include "common/random.h"
#include "exploration/exploration_spec.h"
#include "exploration/frame_maps.h"
#include "tools/cmm/latency.h"

namespace relmap::tools {
namespace {

constexpr std::string_view kUsage =
    "usage: relmap-cmm --train train.csv [--test test.csv]\n"
    "                  [--variant corrected|corrected_v1|paper2018 | --config SPEC]\n"
    "                  [--alpha 0.25] [--regularization 1e-6] [--seed N] [--active]\n"
    "                  [--budget N] [--picks-out picks.txt] [--exploration SPEC]\n"
    "                  [--pool-frames train.csv.frames [--moved-with-target]]\n"
    "                  [--curve N [--curve-csv curve.csv]]\n"
    "  CSV rows: label,f1,...,fp (label 0 or 1; a header line is allowed).\n"
    "  --config   a variant with options changed, e.g. corrected:acceptance=training\n"
    "             (keys: alpha, regularization, pseudo_samples, variance_floor,\n"
    "             covariance, acceptance, overlap, prediction; see docs/method.md)\n"
    "  --active   the choice map picks each next sample from the training pool\n"
    "  --budget   with --active: stop after N picks (default: the whole pool)\n"
    "  --picks-out  with --active: write the picked training rows (0-based, in pick\n"
    "             order), so that another learner can be trained on the same samples\n"
    "  --exploration  with --active: the choice map's options, 'paper' (default) or\n"
    "             'novelty', 'random=0.1', 'novelty,random=0.1' (docs/method.md §4.4)\n"
    "  --pool-frames  with --active: each row's frame (relmap-sim dataset's FILE.csv.frames);\n"
    "             step t picks from frame t mod F's unpicked rows, as relmap-sim run picks\n"
    "             from one frame at a time, instead of from the whole pool\n"
    "  --moved-with-target  with --pool-frames: a moveable pick also labels the other\n"
    "             rows of its frame that show the same body (the file's second column),\n"
    "             as PostOutcomeRequest.moved_supervoxels does (docs/method.md §4.5)\n"
    "  --object-labels  with --pool-frames: every pick labels those rows with its own\n"
    "             label, as PostOutcomeRequest.object_supervoxels and relmap-sim run\n"
    "             --labels object do\n"
    "  --curve    score the test set every N samples (a learning curve)\n"
    "  --curve-csv  also write that curve as CSV (for relmap-plot)\n";

struct Options {
  std::string train;
  std::string test;
  cmm::CmmConfig config;
  bool active = false;
  int budget = -1;
  std::string picks_out;
  exploration::ExplorationConfig exploration;
  std::string pool_frames;
  bool moved_with_target = false;
  bool object_labels = false;
  int curve_every = 0;
  std::string curve_csv;
};

// One point of the learning curve: test scores after `samples` updates.
struct CurvePoint {
  int samples = 0;
  int components[2] = {0, 0};
  std::optional<double> soft_accuracy;
  std::optional<double> thresholded_accuracy;
  double accuracy_at_half = 0.0;
};

[[noreturn]] void Fail(const std::string& message) { ExitWithError("relmap-cmm", message); }

double ParseNumber(std::string_view flag, const char* text) {
  return ParseNumberOrExit("relmap-cmm", flag, text);
}

Options ParseArguments(int argc, char** argv) {
  Options options;
  std::string variant = "corrected";
  std::string exploration_spec = "paper";
  std::optional<double> alpha, regularization, seed;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) Fail(fmt::format("{} needs a value\n{}", flag, kUsage));
      return argv[++i];
    };
    if (flag == "--train")
      options.train = value();
    else if (flag == "--test")
      options.test = value();
    else if (flag == "--variant" || flag == "--config")
      variant = value();
    else if (flag == "--alpha")
      alpha = ParseNumber(flag, value());
    else if (flag == "--regularization")
      regularization = ParseNumber(flag, value());
    else if (flag == "--seed")
      seed = ParseNumber(flag, value());
    else if (flag == "--active")
      options.active = true;
    else if (flag == "--budget")
      options.budget = static_cast<int>(ParseNumber(flag, value()));
    else if (flag == "--picks-out")
      options.picks_out = value();
    else if (flag == "--exploration")
      exploration_spec = value();
    else if (flag == "--pool-frames")
      options.pool_frames = value();
    else if (flag == "--moved-with-target")
      options.moved_with_target = true;
    else if (flag == "--object-labels")
      options.object_labels = true;
    else if (flag == "--curve")
      options.curve_every = static_cast<int>(ParseNumber(flag, value()));
    else if (flag == "--curve-csv")
      options.curve_csv = value();
    else if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      std::exit(0);
    } else {
      Fail(fmt::format("unknown argument '{}'\n{}", flag, kUsage));
    }
  }
  if (options.train.empty()) Fail(fmt::format("--train is required\n{}", kUsage));
  const auto parsed = cmm::ParseConfiguration(variant);
  if (!parsed.ok()) Fail(parsed.status().message());
  options.config = *parsed;
  if (alpha) options.config.alpha = *alpha;
  if (regularization) options.config.regularization = *regularization;
  if (seed) {
    if (*seed < 0) Fail("--seed must be a non-negative integer");
    options.config.seed = static_cast<std::uint64_t>(*seed);
  }
  if (const Status status = cmm::Validate(options.config); !status.ok()) Fail(status.message());
  if (options.curve_every < 0 || (options.active && options.budget == 0)) {
    Fail("--curve and --budget must be positive");
  }
  if (!options.picks_out.empty() && !options.active) Fail("--picks-out needs --active");
  if (!options.pool_frames.empty() && !options.active) Fail("--pool-frames needs --active");
  if ((options.moved_with_target || options.object_labels) && options.pool_frames.empty()) {
    Fail("--moved-with-target and --object-labels need --pool-frames");
  }
  if (exploration_spec != "paper" && !options.active) Fail("--exploration needs --active");
  options.exploration = exploration::ExplorationConfig::ForVariant(options.config.variant);
  if (const Status status =
          exploration::ApplyExplorationSpec(exploration_spec, options.exploration);
      !status.ok()) {
    Fail(status.message());
  }
  if (!options.curve_csv.empty() && (options.curve_every == 0 || options.test.empty())) {
    Fail("--curve-csv needs --curve N and --test");
  }
  return options;
}

datasets::LabelledSamples Load(const std::string& path) {
  auto samples = datasets::ReadLabelledCsv(path);
  if (!samples.ok()) Fail(samples.status().message());
  return std::move(samples).value();
}

std::string Number(std::optional<double> value) {
  return value && std::isfinite(*value) ? fmt::format("{:.6g}", *value) : "null";
}

std::string ScoresJson(const metrics::Scores& s) {
  return fmt::format(R"({{"precision":{},"recall":{},"accuracy":{}}})", Number(s.precision),
                     Number(s.recall), Number(s.accuracy));
}

std::string LatencyJson(const LatencyRecorder::Summary& s) {
  return fmt::format(R"({{"p50":{:.1f},"p99":{:.1f},"max":{:.1f},"count":{}}})", s.p50, s.p99,
                     s.max, s.count);
}

struct TestScores {
  metrics::Scores soft;
  metrics::Scores thresholded;
  double accuracy_at_half = 0.0;  // fraction of samples on the right side of 0.5
  std::optional<double> balanced_accuracy, log_loss, brier;
};

TestScores Score(const cmm::CollaborativeMixtureModels& model,
                 const datasets::LabelledSamples& test) {
  const Eigen::VectorXd p = model.Predict(test.features);
  const std::vector<bool> moveable(test.labels.begin(), test.labels.end());
  TestScores scores{metrics::SoftScores(p, moveable),
                    metrics::ThresholdedSoftScores(p, moveable),
                    0.0,
                    metrics::BalancedAccuracy(p, moveable),
                    metrics::LogLoss(p, moveable),
                    metrics::BrierScore(p, moveable)};
  int right = 0;
  for (Eigen::Index i = 0; i < p.size(); ++i) right += (p[i] >= 0.5) == moveable[i] ? 1 : 0;
  scores.accuracy_at_half = static_cast<double>(right) / static_cast<double>(p.size());
  return scores;
}

class Run {
 public:
  Run(Options options, datasets::LabelledSamples train,
      std::optional<datasets::LabelledSamples> test)
      : options_(std::move(options)),
        train_(std::move(train)),
        test_(std::move(test)),
        model_(cmm::CollaborativeMixtureModels::Create(options_.config,
                                                       static_cast<int>(train_.features.cols()))
                   .value()),
        // The target draws get their own stream, so that --active leaves the
        // classifier's re-check stream as it is online.
        sampler_(options_.config.seed ^ 0x5eed5eed5eed5eedULL) {}

  // The learning curve as CSV, one row per point; undefined scores are empty.
  void WriteCurveCsv() const {
    std::FILE* file = std::fopen(options_.curve_csv.c_str(), "w");
    if (file == nullptr) Fail("cannot write " + options_.curve_csv);
    std::fputs(
        "samples,components_0,components_1,soft_accuracy,thresholded_accuracy,accuracy_at_0_5\n",
        file);
    const auto cell = [](std::optional<double> v) { return v ? fmt::format("{:.6g}", *v) : ""; };
    for (const CurvePoint& c : curve_) {
      std::fputs(
          fmt::format("{},{},{},{},{},{:.6g}\n", c.samples, c.components[0], c.components[1],
                      cell(c.soft_accuracy), cell(c.thresholded_accuracy), c.accuracy_at_half)
              .c_str(),
          file);
    }
    std::fclose(file);
  }

  void Execute() {
    if (options_.active) {
      ExploreThePool();
    } else {
      for (Eigen::Index i = 0; i < train_.features.rows(); ++i) Learn(static_cast<int>(i));
    }
    if (!options_.curve_csv.empty()) WriteCurveCsv();
    if (!options_.picks_out.empty()) WritePicks();
  }

  // The training rows --active picked, one 0-based index per line, in pick order.
  void WritePicks() const {
    std::FILE* file = std::fopen(options_.picks_out.c_str(), "w");
    if (file == nullptr) Fail("cannot write " + options_.picks_out);
    for (const int row : picks_) std::fprintf(file, "%d\n", row);
    std::fclose(file);
  }

  std::string Report() {
    std::string curve;
    for (const CurvePoint& c : curve_) {
      curve += fmt::format(
          R"({}{{"samples":{},"components":[{},{}],"soft_accuracy":{},"thresholded_accuracy":{},"accuracy_at_0_5":{:.6g}}})",
          curve.empty() ? "" : ",", c.samples, c.components[0], c.components[1],
          Number(c.soft_accuracy), Number(c.thresholded_accuracy), c.accuracy_at_half);
    }
    std::string test = "null";
    if (test_) {
      const TestScores s = Score(model_, *test_);
      test = fmt::format(
          R"({{"samples":{},"soft":{},"thresholded_soft":{},"accuracy_at_0_5":{:.6g},)"
          R"("balanced_accuracy":{},"log_loss":{},"brier":{}}})",
          test_->labels.size(), ScoresJson(s.soft), ScoresJson(s.thresholded), s.accuracy_at_half,
          Number(s.balanced_accuracy), Number(s.log_loss), Number(s.brier));
    }
    const LatencyRecorder& predict = test_ ? PredictLatencyOn(*test_) : PredictLatencyOn(train_);
    return fmt::format(
        R"({{"variant":"{}","configuration":"{}","alpha":{},"regularization":{},"temperature":{},)"
        R"("seed":{},"mode":"{}","dimension":{},)"
        R"("samples":[{},{}],"components":[{},{}],"splits":{},"merges":{},"log_likelihood":{},)"
        R"("test":{},"latency_us":{{"update":{},"predict":{},"choice":{}}},"curve":[{}]}})",
        cmm::VariantName(options_.config.variant), cmm::ConfigurationName(options_.config),
        options_.config.alpha, options_.config.regularization, model_.temperature(),
        options_.config.seed, options_.active ? "active" : "online", model_.dimension(),
        model_.sample_count(0), model_.sample_count(1), model_.component_count(0),
        model_.component_count(1), model_.splits(), model_.merges(), Number(model_.LogLikelihood()),
        test, LatencyJson(update_.Summarise()), LatencyJson(predict.Summarise()),
        LatencyJson(choice_.Summarise()), curve);
  }

 private:
  void Learn(int row) {
    const auto report = update_.Time(
        [&] { return model_.Add(train_.features.row(row).transpose(), train_.labels[row]); });
    if (!report.ok())
      Fail(fmt::format("{}: sample {}: {}", options_.train, row + 1, report.status().message()));
    const int n = model_.dataset().size();
    if (test_ && options_.curve_every > 0 && n % options_.curve_every == 0) {
      const TestScores s = Score(model_, *test_);
      curve_.push_back({n,
                        {model_.component_count(0), model_.component_count(1)},
                        s.soft.accuracy,
                        s.thresholded.accuracy,
                        s.accuracy_at_half});
    }
  }

  // The paper's exploration on a fixed pool: each step maps the remaining
  // samples (of the step's frame, with --pool-frames) and lets the choice map
  // pick the next one to label.
  void ExploreThePool() {
    std::vector<std::vector<int>> pools = Pools();
    std::size_t remaining = 0;
    for (const auto& pool : pools) remaining += pool.size();
    const int budget = options_.budget > 0
                           ? std::min<int>(options_.budget, static_cast<int>(remaining))
                           : static_cast<int>(remaining);
    Eigen::MatrixXd candidates;
    std::size_t frame = 0;
    const auto all_empty = [&] {
      return std::all_of(pools.begin(), pools.end(), [](const auto& p) { return p.empty(); });
    };
    for (int step = 0; step < budget && !all_empty(); ++step) {
      while (pools[frame].empty()) frame = (frame + 1) % pools.size();
      std::vector<int>& pool = pools[frame];
      const int pick = choice_.Time([&] {
        candidates.resize(static_cast<Eigen::Index>(pool.size()), train_.features.cols());
        for (std::size_t j = 0; j < pool.size(); ++j) {
          candidates.row(static_cast<Eigen::Index>(j)) = train_.features.row(pool[j]);
        }
        return exploration::ComputeFrameMaps(model_, candidates, options_.exploration, step,
                                             &sampler_)
            .target;
      });
      const int row = pool[static_cast<std::size_t>(pick)];
      picks_.push_back(row);
      Learn(row);
      pool[static_cast<std::size_t>(pick)] = pool.back();
      pool.pop_back();
      if (options_.object_labels ||
          (options_.moved_with_target && train_.labels[static_cast<std::size_t>(row)] == 1)) {
        LearnTheRestOfItsBody(row, pool);
      }
      frame = (frame + 1) % pools.size();
    }
  }

  // The other rows of `row`'s frame pool that show its body, learned (with the label
  // they share with it) and taken out of the pool, in row order.
  void LearnTheRestOfItsBody(int row, std::vector<int>& pool) {
    const int body = bodies_[static_cast<std::size_t>(row)];
    if (body < 0) return;
    std::vector<int> same;
    std::erase_if(pool, [&](int other) {
      const bool match = bodies_[static_cast<std::size_t>(other)] == body;
      if (match) same.push_back(other);
      return match;
    });
    std::sort(same.begin(), same.end());
    for (const int other : same) {
      picks_.push_back(other);
      Learn(other);
    }
  }

  // The candidate rows per frame in frame order: one pool of every row without
  // --pool-frames.
  std::vector<std::vector<int>> Pools() {
    const auto rows = static_cast<int>(train_.features.rows());
    if (options_.pool_frames.empty()) {
      std::vector<int> all(static_cast<std::size_t>(rows));
      for (int i = 0; i < rows; ++i) all[static_cast<std::size_t>(i)] = i;
      return {all};
    }
    std::FILE* file = std::fopen(options_.pool_frames.c_str(), "r");
    if (file == nullptr) Fail("cannot read " + options_.pool_frames);
    std::map<long, std::vector<int>> by_frame;
    char line[64];
    int row = 0;
    while (std::fgets(line, sizeof line, file) != nullptr) {
      char* end = nullptr;
      const long frame = std::strtol(line, &end, 10);
      if (end == line) continue;  // the header
      if (row >= rows) break;
      // "frame,body" since relmap-sim dataset writes bodies; "frame" before.
      bodies_.push_back(*end == ',' ? static_cast<int>(std::strtol(end + 1, nullptr, 10)) : -1);
      by_frame[frame].push_back(row++);
    }
    std::fclose(file);
    if (row != rows) {
      Fail(fmt::format("{} gives a frame for {} rows, {} has {}", options_.pool_frames, row,
                       options_.train, rows));
    }
    std::vector<std::vector<int>> pools;
    pools.reserve(by_frame.size());
    for (auto& [frame, members] : by_frame) pools.push_back(std::move(members));
    return pools;
  }

  LatencyRecorder& PredictLatencyOn(const datasets::LabelledSamples& samples) {
    const Eigen::Index n = std::min<Eigen::Index>(samples.features.rows(), 2000);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::MatrixXd one = samples.features.row(i);
      predict_.Time([&] { return model_.Predict(one); });
    }
    return predict_;
  }

  Options options_;
  datasets::LabelledSamples train_;
  std::optional<datasets::LabelledSamples> test_;
  cmm::CollaborativeMixtureModels model_;
  Random sampler_;
  LatencyRecorder update_, predict_, choice_;
  std::vector<CurvePoint> curve_;
  std::vector<int> picks_;   // --active: the rows picked, in order
  std::vector<int> bodies_;  // --pool-frames: each row's body, -1 for none
};

}  // namespace
}  // namespace relmap::tools

int main(int argc, char** argv) {
  using namespace relmap;
  tools::Options options = tools::ParseArguments(argc, argv);
  datasets::LabelledSamples train = tools::Load(options.train);
  std::optional<datasets::LabelledSamples> test;
  if (!options.test.empty()) {
    test = tools::Load(options.test);
    if (test->features.cols() != train.features.cols()) {
      tools::Fail(fmt::format("{} has {} features per row, {} has {}", options.test,
                              test->features.cols(), options.train, train.features.cols()));
    }
  }
  tools::Run run(std::move(options), std::move(train), std::move(test));
  run.Execute();
  std::printf("%s\n", run.Report().c_str());
  return 0;
}
