// The stream variants of the learning benchmark: class imbalance, constant
// dimensions, label noise of an exact rate and the map into [0, 1].
#include "datasets/synthetic_problems.h"

#include <gtest/gtest.h>

namespace relmap::datasets {
namespace {

ProblemOptions Xor48() {
  ProblemOptions options;
  options.problem = Problem::kXorBlobs;
  options.samples = 2000;
  options.dimension = 48;
  return options;
}

TEST(SyntheticProblems, PositiveFractionSetsTheClassBalance) {
  ProblemOptions options = Xor48();
  options.positive_fraction = 0.2;
  const LabelledSamples s = MakeProblem(options);
  int positives = 0;
  for (const int label : s.labels) positives += label;
  // Binomial(2000, 0.2): mean 400, standard deviation ≈ 17.9; ±4σ ≈ ±72.
  EXPECT_NEAR(positives, 400, 72);
}

TEST(SyntheticProblems, ConstantDimensionsAreExactlyZeroAndTheOthersVary) {
  ProblemOptions options = Xor48();
  options.constant_dimensions = 8;
  const LabelledSamples s = MakeProblem(options);
  EXPECT_EQ(s.features.cols(), 48);
  EXPECT_EQ(s.features.rightCols(8).cwiseAbs().maxCoeff(), 0.0);
  for (int j = 0; j < 40; ++j) EXPECT_GT(s.features.col(j).cwiseAbs().maxCoeff(), 0.0) << j;
}

TEST(SyntheticProblems, FlipLabelsFlipsExactlyTheRoundedFraction) {
  const LabelledSamples clean = MakeProblem(Xor48());
  LabelledSamples noisy = clean;
  FlipLabels(noisy, 0.1, 7);
  int changed = 0;
  for (std::size_t i = 0; i < clean.labels.size(); ++i) {
    changed += clean.labels[i] != noisy.labels[i] ? 1 : 0;
  }
  EXPECT_EQ(changed, 200);  // round(0.1 · 2000)
  EXPECT_EQ(noisy.features, clean.features);
}

TEST(SyntheticProblems, UnitRangeMapsTheReferenceOntoZeroOne) {
  // Column 0 spans [−1, 3] in the reference: x ↦ (x + 1)/4, so 1 ↦ 0.5 and 5
  // clips to 1; column 1 is constant and maps to 0.
  Eigen::MatrixXd reference(3, 2);
  reference << -1, 2, 3, 2, 0, 2;
  Eigen::MatrixXd other(2, 2);
  other << 1, 7, 5, 2;
  const Eigen::MatrixXd mapped = MapToUnitRange(reference, other);
  EXPECT_DOUBLE_EQ(mapped(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(mapped(1, 0), 1.0);
  EXPECT_DOUBLE_EQ(mapped(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(MapToUnitRange(reference, reference).col(0).minCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(MapToUnitRange(reference, reference).col(0).maxCoeff(), 1.0);
}

}  // namespace
}  // namespace relmap::datasets
