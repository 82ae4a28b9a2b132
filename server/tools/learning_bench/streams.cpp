// The suite's table and the seeds of each replication.
#include "learning_bench/streams.h"

#include <array>
#include <cmath>
#include <string>

#include "common/labelled_csv.h"
#include "common/random.h"

namespace relmap::learning_bench {
namespace {

using datasets::Problem;

// 48 dimensions like the real features; 8 constant like the empty colour bins of
// the 2018 colour conversion; 1:4 imbalance, moveable (class 1) the rare class,
// as objects are rarer than background in a scene.
constexpr std::array kSuite = {
    StreamSpec{"moons2d", Problem::kTwoMoons, 2},
    StreamSpec{"xor2d", Problem::kXorBlobs, 2},
    StreamSpec{"rings2d", Problem::kConcentricRings, 2},
    StreamSpec{"moons48", Problem::kTwoMoons, 48},
    StreamSpec{"xor48", Problem::kXorBlobs, 48},
    StreamSpec{"rings48", Problem::kConcentricRings, 48},
    StreamSpec{"xor48-flip10", Problem::kXorBlobs, 48, 0.10},
    StreamSpec{"xor48-flip20", Problem::kXorBlobs, 48, 0.20},
    StreamSpec{"moons48-flip20", Problem::kTwoMoons, 48, 0.20},
    StreamSpec{"xor48-imbalanced", Problem::kXorBlobs, 48, 0.0, 0.2},
    StreamSpec{"xor48-constant-dims", Problem::kXorBlobs, 48, 0.0, 0.5, 8},
    StreamSpec{"xor48-unit-range", Problem::kXorBlobs, 48, 0.0, 0.5, 0, true},
};

enum class SeedUse { kEmbedding, kTrain, kTest, kFlips };

std::uint64_t DeriveSeed(std::uint64_t seed, int replication, SeedUse use) {
  // One splitmix64-seeded draw per (seed, replication, use): unrelated streams
  // for neighbouring inputs.
  Random random(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(replication) * 4 +
                static_cast<std::uint64_t>(use));
  return random.NextBits();
}

}  // namespace

std::span<const StreamSpec> BuiltInStreams() { return kSuite; }

const StreamSpec* FindBuiltInStream(std::string_view name) {
  for (const StreamSpec& spec : kSuite) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

Stream MakeStream(const StreamSpec& spec, StreamSizes sizes, std::uint64_t seed, int replication) {
  datasets::ProblemOptions options;
  options.problem = spec.problem;
  options.dimension = spec.dimension;
  options.positive_fraction = spec.positive_fraction;
  options.constant_dimensions = spec.constant_dimensions;
  options.embedding_seed = DeriveSeed(seed, replication, SeedUse::kEmbedding);

  Stream stream{std::string(spec.name), {}, {}};
  options.samples = sizes.train;
  options.seed = DeriveSeed(seed, replication, SeedUse::kTrain);
  stream.train = datasets::MakeProblem(options);
  options.samples = sizes.test;
  options.seed = DeriveSeed(seed, replication, SeedUse::kTest);
  stream.test = datasets::MakeProblem(options);

  datasets::FlipLabels(stream.train, spec.flipped_training_labels,
                       DeriveSeed(seed, replication, SeedUse::kFlips));
  if (spec.unit_range) {
    stream.test.features = datasets::MapToUnitRange(stream.train.features, stream.test.features);
    stream.train.features = datasets::MapToUnitRange(stream.train.features, stream.train.features);
  }
  return stream;
}

Stream FlippedStream(const Stream& stream, double fraction, std::uint64_t seed) {
  Stream flipped = stream;
  flipped.name += "-flip" + std::to_string(std::llround(100.0 * fraction));
  datasets::FlipLabels(flipped.train, fraction, DeriveSeed(seed, 0, SeedUse::kFlips));
  return flipped;
}

StatusOr<Stream> LoadStream(std::string name, const std::string& train_csv,
                            const std::string& test_csv) {
  auto train = datasets::ReadLabelledCsv(train_csv);
  if (!train.ok()) return train.status();
  auto test = datasets::ReadLabelledCsv(test_csv);
  if (!test.ok()) return test.status();
  if (train->features.cols() != test->features.cols()) {
    return InvalidArgumentError(test_csv + " has " + std::to_string(test->features.cols()) +
                                " features per row, " + train_csv + " has " +
                                std::to_string(train->features.cols()));
  }
  return Stream{std::move(name), std::move(train).value(), std::move(test).value()};
}

}  // namespace relmap::learning_bench
