// relmap-bench-learning: every learner, online, on the same labelled streams in
// the same order, scored on held-out sets; prints one side-by-side table and
// writes it as CSV and JSON with learning-curve PNGs (--out).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/command_line.h"
#include "common/labelled_csv.h"
#include "learning_bench/curve_plot.h"
#include "learning_bench/evaluation.h"
#include "learning_bench/learners.h"
#include "learning_bench/reference.h"
#include "learning_bench/report_json.h"
#include "learning_bench/streams.h"
#include "learning_bench/summary.h"
#include "learning_bench/table_csv.h"
#include "learning_bench/table_text.h"

#ifndef RELMAP_REFERENCE_SCRIPT
#define RELMAP_REFERENCE_SCRIPT "scripts/bench-learning-reference.py"
#endif

namespace relmap::learning_bench {
namespace {

constexpr std::string_view kProgram = "relmap-bench-learning";
constexpr std::string_view kUsage =
    "usage: relmap-bench-learning [--learners a,b,...] [--streams a,b,...]\n"
    "         [--stream NAME=TRAIN.csv:TEST.csv ...] [--train-samples 400] [--test-samples 2000]\n"
    "         [--curve 50] [--seed 1] [--replications 3] [--out DIR] [--reference]\n"
    "         [--reference-script PATH] [--flip FRACTION]\n"
    "  --learners  CMM configurations (corrected, corrected:acceptance=training, ...), alpha1 "
    "(corrected with\n"
    "              alpha = 1), gnb, sgd, knn; unknown names are skipped with a warning.\n"
    "              Default: corrected,corrected_v1,paper2018,alpha1,gnb,sgd,knn\n"
    "  --streams   built-in streams (default: the whole suite, or none when --stream\n"
    "              is given): moons2d xor2d rings2d moons48 xor48 rings48 xor48-flip10\n"
    "              xor48-flip20 moons48-flip20 xor48-imbalanced xor48-constant-dims\n"
    "              xor48-unit-range\n"
    "  --stream    an external stream in relmap-cmm's CSV format (label first),\n"
    "              repeatable; run once, as its samples are fixed\n"
    "  --flip      also run each --stream with that fraction of its training labels\n"
    "              flipped (exactly round(FRACTION x n), a subset drawn from --seed),\n"
    "              as NAME-flipPP right after it; FRACTION in (0, 1)\n"
    "  --curve     score the test set every N training samples (learning curves)\n"
    "  --out       write table.csv, table.json, curves.csv, curves/STREAM.png and the\n"
    "              streams as CSV (streams/STREAM.rK.train.csv, .test.csv)\n"
    "  --reference also run the batch random forest, RBF SVM and logistic regression\n"
    "              of scikit-learn on the written streams (needs --out, python3 and\n"
    "              sklearn)\n";

struct Options {
  std::vector<std::string> learners;
  std::vector<std::string> builtin_streams;
  std::vector<std::string> external_streams;  // NAME=TRAIN:TEST
  StreamSizes sizes;
  int curve_every = 50;
  std::uint64_t seed = 1;
  int replications = 3;
  std::string out;
  bool reference = false;
  std::string reference_script = RELMAP_REFERENCE_SCRIPT;
  std::optional<double> flip;  // the fraction of an external stream's labels flipped
};

[[noreturn]] void Fail(const std::string& message) { tools::ExitWithError(kProgram, message); }

std::vector<std::string> SplitList(std::string_view list) {
  std::vector<std::string> out;
  for (std::size_t start = 0; start <= list.size();) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    if (comma > start) out.emplace_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

int PositiveInteger(std::string_view flag, const char* text) {
  const double value = tools::ParseNumberOrExit(kProgram, flag, text);
  if (value < 1 || value != static_cast<int>(value)) {
    Fail(fmt::format("{} expects a positive integer, got '{}'", flag, text));
  }
  return static_cast<int>(value);
}

Options ParseArguments(int argc, char** argv) {
  Options o;
  o.learners = SplitList(kDefaultLearners);
  bool streams_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) Fail(fmt::format("{} needs a value\n{}", flag, kUsage));
      return argv[++i];
    };
    if (flag == "--learners") {
      o.learners = SplitList(value());
    } else if (flag == "--streams") {
      o.builtin_streams = SplitList(value()), streams_given = true;
    } else if (flag == "--stream") {
      o.external_streams.emplace_back(value());
    } else if (flag == "--train-samples") {
      o.sizes.train = PositiveInteger(flag, value());
    } else if (flag == "--test-samples") {
      o.sizes.test = PositiveInteger(flag, value());
    } else if (flag == "--curve") {
      o.curve_every = PositiveInteger(flag, value());
    } else if (flag == "--seed") {
      const double seed = tools::ParseNumberOrExit(kProgram, flag, value());
      if (seed < 0) Fail("--seed must be a non-negative integer");
      o.seed = static_cast<std::uint64_t>(seed);
    } else if (flag == "--replications") {
      o.replications = PositiveInteger(flag, value());
    } else if (flag == "--out") {
      o.out = value();
    } else if (flag == "--reference") {
      o.reference = true;
    } else if (flag == "--reference-script") {
      o.reference_script = value();
    } else if (flag == "--flip") {
      const char* text = value();
      const double fraction = tools::ParseNumberOrExit(kProgram, flag, text);
      if (!(fraction > 0 && fraction < 1)) {
        Fail(fmt::format("--flip expects a fraction in (0, 1), got '{}'", text));
      }
      o.flip = fraction;
    } else if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      std::exit(0);
    } else {
      Fail(fmt::format("unknown argument '{}'\n{}", flag, kUsage));
    }
  }
  if (!streams_given && o.external_streams.empty()) {
    for (const StreamSpec& spec : BuiltInStreams()) o.builtin_streams.emplace_back(spec.name);
  }
  if (o.flip && o.external_streams.empty()) Fail("--flip needs a --stream to flip");
  if (o.reference && o.out.empty())
    Fail("--reference needs --out DIR (it reads the streams there)");
  return o;
}

// The learners that resolve; the others are skipped with a warning, so that a
// list naming a variant this build does not have still runs.
std::vector<std::string> UsableLearners(const std::vector<std::string>& names) {
  std::vector<std::string> usable;
  for (const std::string& name : names) {
    const auto learner = MakeLearner(name, 2, 0);
    if (learner.ok()) {
      usable.push_back(name);
    } else {
      std::fprintf(stderr, "%s: warning: skipping learner '%s': %s\n", kProgram.data(),
                   name.c_str(), learner.status().message().c_str());
    }
  }
  if (usable.empty()) Fail("no usable learner");
  return usable;
}

// The replications of every stream: built-in ones under their derived seeds,
// external ones as they are (a single replication).
std::vector<std::vector<Stream>> LoadStreams(const Options& o) {
  std::vector<std::vector<Stream>> streams;
  for (const std::string& name : o.builtin_streams) {
    const StreamSpec* spec = FindBuiltInStream(name);
    if (spec == nullptr) Fail(fmt::format("unknown stream '{}'\n{}", name, kUsage));
    std::vector<Stream> replications;
    replications.reserve(static_cast<std::size_t>(o.replications));
    for (int r = 0; r < o.replications; ++r) {
      replications.push_back(MakeStream(*spec, o.sizes, o.seed, r));
    }
    streams.push_back(std::move(replications));
  }
  for (const std::string& text : o.external_streams) {
    const std::size_t eq = text.find('='), colon = text.find(':', eq);
    const std::string name = text.substr(0, eq);
    // The name becomes a file name and the reference script splits NAME.rK.
    const bool plain = !name.empty() && name.find_first_not_of(
                                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789_-") == std::string::npos;
    if (eq == std::string::npos || colon == std::string::npos || !plain) {
      Fail(
          fmt::format("--stream expects NAME=TRAIN.csv:TEST.csv with NAME of letters, digits, "
                      "_ and -, got '{}'",
                      text));
    }
    auto stream = LoadStream(name, text.substr(eq + 1, colon - eq - 1), text.substr(colon + 1));
    if (!stream.ok()) Fail(stream.status().message());
    if (o.flip) {
      Stream flipped = FlippedStream(*stream, *o.flip, o.seed);
      streams.push_back({std::move(stream).value()});
      streams.push_back({std::move(flipped)});
    } else {
      streams.push_back({std::move(stream).value()});
    }
  }
  if (streams.empty()) Fail("no stream to run");
  return streams;
}

void WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) Fail("cannot write " + path.string());
}

void WriteStreams(const std::filesystem::path& dir, const std::vector<Stream>& replications) {
  std::filesystem::create_directories(dir);
  for (std::size_t r = 0; r < replications.size(); ++r) {
    const Stream& s = replications[r];
    for (const auto& [part, samples] : {std::pair{"train", &s.train}, std::pair{"test", &s.test}}) {
      std::ofstream out(dir / fmt::format("{}.r{}.{}.csv", s.name, r, part));
      datasets::WriteLabelledCsv(*samples, out);
      if (!out) Fail("cannot write the streams in " + dir.string());
    }
  }
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int Main(int argc, char** argv) {
  const auto start = std::chrono::steady_clock::now();
  const Options o = ParseArguments(argc, argv);
  const std::vector<std::string> learners = UsableLearners(o.learners);
  const std::vector<std::vector<Stream>> streams = LoadStreams(o);
  const std::filesystem::path out(o.out);
  if (!o.out.empty()) {
    // The reference reads every stream file there: none may be left from an
    // earlier run with other streams.
    std::filesystem::remove_all(out / "streams");
    std::filesystem::create_directories(out / "curves");
  }

  std::vector<TableRow> rows;
  std::vector<CurveSummary> curves;
  std::vector<std::string> stream_names;
  const std::size_t total = streams.size() * learners.size();
  for (const std::vector<Stream>& replications : streams) {
    const std::string& name = replications.front().name;
    stream_names.push_back(name);
    if (!o.out.empty()) WriteStreams(out / "streams", replications);
    for (const std::string& learner_name : learners) {
      const auto learner_start = std::chrono::steady_clock::now();
      tools::LatencyRecorder updates;
      std::vector<RunResult> runs;
      for (const Stream& stream : replications) {
        auto learner =
            MakeLearner(learner_name, static_cast<int>(stream.train.features.cols()), o.seed);
        if (!learner.ok()) Fail(learner.status().message());
        auto run = RunLearner(**learner, stream, o.curve_every, updates);
        if (!run.ok()) Fail(learner_name + ": " + run.status().message());
        runs.push_back(std::move(run).value());
      }
      rows.push_back(Summarise(name, learner_name, runs, updates));
      curves.push_back(SummariseCurves(name, learner_name, runs));
      const auto& b = rows.back().balanced_accuracy_mean;
      std::fprintf(stderr, "[%zu/%zu] %s %s: balanced accuracy %s (%.1f s)\n", rows.size(), total,
                   name.c_str(), learner_name.c_str(),
                   b ? fmt::format("{:.3f}", *b).c_str() : "undefined",
                   SecondsSince(learner_start));
    }
  }

  ReferenceOutcome reference{{}, "not run: --reference not given"};
  if (o.reference) {
    std::fprintf(stderr, "reference: %s\n", o.reference_script.c_str());
    reference = RunReference(o.reference_script, (out / "streams").string(),
                             (out / "reference.csv").string(), o.seed);
  }
  std::vector<std::string> reference_names;
  for (const TableRow& r : reference.rows) {
    if (std::find(reference_names.begin(), reference_names.end(), r.learner) ==
        reference_names.end()) {
      reference_names.push_back(r.learner);
    }
  }
  rows.insert(rows.end(), reference.rows.begin(), reference.rows.end());
  // Each stream's reference rows right below its online ones.
  const auto stream_index = [&](const TableRow& r) {
    return std::find(stream_names.begin(), stream_names.end(), r.stream) - stream_names.begin();
  };
  std::stable_sort(rows.begin(), rows.end(), [&](const TableRow& a, const TableRow& b) {
    return stream_index(a) < stream_index(b);
  });
  const std::vector<StreamBest> best = BestPerStream(rows, stream_names, reference_names);

  const double wall = SecondsSince(start);
  std::fputs(FormatTable(rows).c_str(), stdout);
  std::fputs(FormatBestLines(best).c_str(), stdout);
  std::printf("reference (random forest, RBF SVM, logistic regression): %s\n",
              reference.status.c_str());
  std::printf("wall time: %.1f s\n", wall);

  if (!o.out.empty()) {
    const RunSettings settings{o.seed,        o.replications,   o.sizes.train, o.sizes.test,
                               o.curve_every, reference.status, wall};
    WriteFile(out / "table.csv", TableCsv(rows));
    WriteFile(out / "table.json", ReportJson(settings, rows, best, curves));
    WriteFile(out / "curves.csv", CurvesCsv(curves));
    for (const std::string& name : stream_names) {
      const Status status =
          WriteCurvePng(name, curves, (out / "curves" / (name + ".png")).string());
      if (!status.ok()) Fail(status.message());
    }
  }
  return 0;
}

}  // namespace
}  // namespace relmap::learning_bench

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf(relmap::learning_bench::kProgram,
                                   [&] { return relmap::learning_bench::Main(argc, argv); });
}
