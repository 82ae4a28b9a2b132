// Seeded, labelled toy problems for the classifier: the non-convex 2-d classics
// (two moons, XOR blobs, concentric rings), optionally lifted into p dimensions.
// Used by the tests, the benchmarks and the demo stream of `relmap-cmm`.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string_view>
#include <vector>

#include "common/labelled_csv.h"
#include "common/status.h"

namespace relmap::datasets {

enum class Problem { kTwoMoons, kXorBlobs, kConcentricRings };

StatusOr<Problem> ParseProblem(std::string_view name);

struct ProblemOptions {
  Problem problem = Problem::kTwoMoons;
  int samples = 1000;
  // Standard deviation of the Gaussian noise added to the 2-d points.
  double noise = 0.1;
  // p >= 2: the 2-d points are placed on a random 2-d plane of R^p (an
  // orthonormal basis drawn from the seed) and every dimension gets
  // `ambient_noise` of isotropic noise, so that the problem is full rank.
  int dimension = 2;
  double ambient_noise = 0.02;
  // Seed of the samples; the plane of the embedding has its own seed, so that
  // training and test sets drawn with different seeds share one embedding.
  std::uint64_t seed = 1;
  std::uint64_t embedding_seed = 0;
  // Probability that a sample is of class 1 (0.2 gives an imbalance of 1:4).
  double positive_fraction = 0.5;
  // The last `constant_dimensions` of the p dimensions are exactly 0, like the
  // colour bins the 2018 colour conversion never fills (docs/method.md §2); the
  // problem and its ambient noise live in the other p − constant_dimensions.
  int constant_dimensions = 0;
};

// Each sample's class is drawn with probability `positive_fraction`; the same
// options give the same samples on every machine (the generator draws from
// relmap's own RNG).
LabelledSamples MakeProblem(const ProblemOptions& options);

// Flips the labels of round(fraction · n) samples chosen uniformly without
// replacement with `seed`: label noise of an exact rate, features untouched.
void FlipLabels(LabelledSamples& samples, double fraction, std::uint64_t seed);

// `features` with each column mapped by the affine map that takes the range
// [min, max] of that column of `reference` onto [0, 1], then clipped to [0, 1]
// (real features never leave it); a constant column of `reference` maps to 0.
// Map the test set with the training set as reference, so that both share one
// map and the test set tells the learner nothing.
Eigen::MatrixXd MapToUnitRange(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& features);

}  // namespace relmap::datasets
