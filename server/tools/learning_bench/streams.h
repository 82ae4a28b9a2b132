// The labelled streams of the learning benchmark: a built-in suite of toy
// problems and their hard variants (label noise, imbalance, constant dimensions,
// features in [0, 1]), and external streams read from CSV files.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "datasets/synthetic_problems.h"

namespace relmap::learning_bench {

struct Stream {
  std::string name;
  datasets::LabelledSamples train;  // learned in row order
  datasets::LabelledSamples test;   // held out, clean labels
};

// A built-in stream: a problem of datasets::MakeProblem and what is done to it.
struct StreamSpec {
  std::string_view name;
  datasets::Problem problem;
  int dimension;
  double flipped_training_labels = 0.0;  // fraction; test labels stay clean
  double positive_fraction = 0.5;        // of training and test alike
  int constant_dimensions = 0;
  // Every dimension of both sets mapped into [0, 1] by the affine map of the
  // training range (datasets::MapToUnitRange), like the real features.
  bool unit_range = false;
};

// The default suite, in the order the table lists it.
std::span<const StreamSpec> BuiltInStreams();
// The built-in stream of that name, or nullptr.
const StreamSpec* FindBuiltInStream(std::string_view name);

struct StreamSizes {
  int train = 400;  // a real robot run (docs/method.md §7)
  int test = 2000;
};

// Replication `replication` of a built-in stream under the run's `seed`. The
// seeds of the embedding, training set, test set and flipped labels derive from
// (seed, replication) only, not from the stream's name: the variants of a
// problem share the samples of the plain stream, so that a difference in the
// table is the variant's doing.
Stream MakeStream(const StreamSpec& spec, StreamSizes sizes, std::uint64_t seed, int replication);

// `stream` with exactly round(fraction × n) of its n training labels flipped, a
// uniform subset drawn from `seed` (datasets::FlipLabels), its test set as it is:
// the label noise of a change detector that is wrong on some pushes, reproducibly.
// Named "<name>-flip<percent>", the percent rounded to a whole number.
Stream FlippedStream(const Stream& stream, double fraction, std::uint64_t seed);

// An external stream in relmap-cmm's CSV format (label first). Unreadable or
// malformed files, or sets of different dimensions → an error naming the file.
StatusOr<Stream> LoadStream(std::string name, const std::string& train_csv,
                            const std::string& test_csv);

}  // namespace relmap::learning_bench
