// Generators of the toy problems. Gaussian draws use Box-Muller on relmap's
// xoshiro stream rather than std::normal_distribution, whose output differs
// between standard libraries.
#include "datasets/synthetic_problems.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/random.h"

namespace relmap::datasets {
namespace {

class Gaussian {
 public:
  explicit Gaussian(Random& random) : random_(random) {}
  double operator()() {
    // Box-Muller; 1 − U keeps the logarithm finite.
    const double radius = std::sqrt(-2.0 * std::log(1.0 - random_.UniformUnit()));
    return radius * std::cos(2.0 * std::numbers::pi * random_.UniformUnit());
  }

 private:
  Random& random_;
};

Eigen::Vector2d PlanePoint(Problem problem, int label, Random& random) {
  const double pi = std::numbers::pi;
  const double t = random.UniformUnit();
  switch (problem) {
    case Problem::kTwoMoons:
      // Upper moon (label 0) centred at 0, lower moon (label 1) shifted by (1, 0.5).
      if (label == 0) return {std::cos(pi * t), std::sin(pi * t)};
      return {1.0 - std::cos(pi * t), 0.5 - std::sin(pi * t)};
    case Problem::kXorBlobs: {
      // A 4×4 checkerboard of blobs one unit apart, class = parity of the cell.
      // (The 2×2 XOR is no test: its classes differ in correlation, and one
      // Gaussian per class separates them.)
      for (;;) {
        const auto i = static_cast<int>(random.UniformIndex(4));
        const auto j = static_cast<int>(random.UniformIndex(4));
        if ((i + j) % 2 == label) return {i - 1.5, j - 1.5};
      }
    }
    case Problem::kConcentricRings: {
      // Radii 1 and 3 for label 1, 2 for label 0: interleaved, so that the two
      // classes have nearly the same mean and covariance.
      const double radius = label == 1 ? (random.UniformUnit() < 0.5 ? 1.0 : 3.0) : 2.0;
      return {radius * std::cos(2 * pi * t), radius * std::sin(2 * pi * t)};
    }
  }
  return {0.0, 0.0};
}

}  // namespace

StatusOr<Problem> ParseProblem(std::string_view name) {
  if (name == "moons") return Problem::kTwoMoons;
  if (name == "xor") return Problem::kXorBlobs;
  if (name == "rings") return Problem::kConcentricRings;
  return InvalidArgumentError("unknown problem '" + std::string(name) +
                              "' (expected moons, xor or rings)");
}

LabelledSamples MakeProblem(const ProblemOptions& options) {
  Random random(options.seed);
  Gaussian gaussian(random);
  const int p = std::max(2, options.dimension);
  const int constant = std::clamp(options.constant_dimensions, 0, p - 2);
  const int varying = p - constant;

  Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(varying, 2);
  if (varying > 2) {
    Random embedding_random(options.embedding_seed);
    Gaussian embedding_gaussian(embedding_random);
    Eigen::MatrixXd draw(varying, 2);
    for (int i = 0; i < draw.size(); ++i) draw.data()[i] = embedding_gaussian();
    basis = Eigen::HouseholderQR<Eigen::MatrixXd>(draw).householderQ() *
            Eigen::MatrixXd::Identity(varying, 2);
  }

  LabelledSamples out;
  out.features.resize(options.samples, p);
  out.labels.resize(options.samples);
  for (int i = 0; i < options.samples; ++i) {
    // The balanced case keeps its historical draw, so that its streams (and the
    // tests built on them) stay the same samples.
    const int label = options.positive_fraction == 0.5
                          ? static_cast<int>(random.UniformIndex(2))
                          : (random.UniformUnit() < options.positive_fraction ? 1 : 0);
    Eigen::Vector2d plane = PlanePoint(options.problem, label, random);
    plane += options.noise * Eigen::Vector2d(gaussian(), gaussian());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(p);
    x.head(varying) = basis * plane;
    if (varying > 2) {
      for (int k = 0; k < varying; ++k) x[k] += options.ambient_noise * gaussian();
    }
    out.features.row(i) = x.transpose();
    out.labels[i] = label;
  }
  return out;
}

void FlipLabels(LabelledSamples& samples, double fraction, std::uint64_t seed) {
  const auto n = samples.labels.size();
  const auto flips = static_cast<std::size_t>(
      std::llround(std::clamp(fraction, 0.0, 1.0) * static_cast<double>(n)));
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  // The first `flips` steps of a Fisher-Yates shuffle: a uniform subset.
  Random random(seed);
  for (std::size_t i = 0; i < flips; ++i) {
    std::swap(order[i], order[i + random.UniformIndex(n - i)]);
    samples.labels[order[i]] = 1 - samples.labels[order[i]];
  }
}

Eigen::MatrixXd MapToUnitRange(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& features) {
  Eigen::MatrixXd out(features.rows(), features.cols());
  for (Eigen::Index j = 0; j < features.cols(); ++j) {
    const double low = reference.col(j).minCoeff();
    const double range = reference.col(j).maxCoeff() - low;
    if (range == 0.0) {
      out.col(j).setZero();
    } else {
      out.col(j) = ((features.col(j).array() - low) / range).cwiseMax(0.0).cwiseMin(1.0);
    }
  }
  return out;
}

}  // namespace relmap::datasets
