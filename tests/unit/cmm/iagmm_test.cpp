// Behaviour of Algorithm IAGMM on non-convex problems: more components beat one,
// splits and merges happen where the classes overlap, and runs are reproducible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "common/metrics.h"
#include "common/random.h"
#include "datasets/synthetic_problems.h"
#include "support/cmm_training.h"

namespace relmap::cmm {
namespace {

using datasets::LabelledSamples;
using datasets::MakeProblem;
using datasets::Problem;
using datasets::ProblemOptions;
using testing::Train;

// The paper's soft accuracy (§6): the mean probability given to the true class,
// averaged over the two classes.
double SoftAccuracy(const CollaborativeMixtureModels& model, const LabelledSamples& test) {
  std::vector<bool> moveable(test.labels.begin(), test.labels.end());
  return metrics::SoftScores(model.Predict(test.features), moveable).accuracy.value();
}

// Fraction of test samples on the right side of 0.5.
double HardAccuracy(const CollaborativeMixtureModels& model, const LabelledSamples& test) {
  const Eigen::VectorXd p = model.Predict(test.features);
  int correct = 0;
  for (int i = 0; i < p.size(); ++i) correct += ((p[i] >= 0.5) == (test.labels[i] == 1)) ? 1 : 0;
  return static_cast<double>(correct) / static_cast<double>(p.size());
}

struct ProblemCase {
  Problem problem;
  int dimension;
};

class NonConvexProblem : public ::testing::TestWithParam<ProblemCase> {};

TEST_P(NonConvexProblem, CorrectedCmmBeatsOneComponentPerClass) {
  ProblemOptions options;
  options.problem = GetParam().problem;
  options.dimension = GetParam().dimension;
  options.samples = 600;
  options.seed = 11;
  const LabelledSamples train = MakeProblem(options);
  options.samples = 2000;
  options.seed = 12;
  const LabelledSamples test = MakeProblem(options);

  CmmConfig cmm;  // corrected, α = 0.25
  CmmConfig single;
  single.alpha = 1.0;  // T = 0: no split, no merge
  const auto many = Train(train, cmm);
  const auto one = Train(train, single);
  EXPECT_EQ(one.component_count(0) + one.component_count(1), 2);
  EXPECT_GT(many.component_count(0) + many.component_count(1), 2);
  const double many_accuracy = HardAccuracy(many, test);
  const double one_accuracy = HardAccuracy(one, test);
  std::printf(
      "soft accuracy %.3f hard %.3f with %d+%d components; %.3f hard %.3f with one per class\n",
      SoftAccuracy(many, test), many_accuracy, many.component_count(0), many.component_count(1),
      SoftAccuracy(one, test), one_accuracy);
  EXPECT_GT(many_accuracy, one_accuracy + 0.05);
  EXPECT_GT(many_accuracy, 0.9);
}

std::string CaseName(const ::testing::TestParamInfo<ProblemCase>& info) {
  switch (info.param.problem) {
    case Problem::kTwoMoons:
      return "TwoMoons";
    case Problem::kXorBlobs:
      return "XorBlobs";
    case Problem::kConcentricRings:
      return "ConcentricRings";
  }
  return "Unknown";
}

INSTANTIATE_TEST_SUITE_P(TwoDimensional, NonConvexProblem,
                         ::testing::Values(ProblemCase{Problem::kTwoMoons, 2},
                                           ProblemCase{Problem::kXorBlobs, 2},
                                           ProblemCase{Problem::kConcentricRings, 2}),
                         CaseName);

// The same problems on a plane of R^48 with ambient noise in every dimension,
// at the default α: what the first corrected variant could not learn (0.50).
INSTANTIATE_TEST_SUITE_P(FortyEightDimensional, NonConvexProblem,
                         ::testing::Values(ProblemCase{Problem::kTwoMoons, 48},
                                           ProblemCase{Problem::kXorBlobs, 48},
                                           ProblemCase{Problem::kConcentricRings, 48}),
                         CaseName);

TEST(Iagmm, TwentyPercentFlippedLabelsCostLittle) {
  // XOR blobs in 48-d, 600 samples, a fifth of the training labels flipped
  // (what a change detector's mistakes do); tested on clean labels.
  datasets::ProblemOptions options;
  options.problem = Problem::kXorBlobs;
  options.dimension = 48;
  options.samples = 600;
  options.seed = 31;
  const LabelledSamples clean = MakeProblem(options);
  LabelledSamples noisy = clean;
  datasets::FlipLabels(noisy, 0.2, 32);
  options.samples = 2000;
  options.seed = 33;
  const LabelledSamples test = MakeProblem(options);
  const double clean_accuracy = HardAccuracy(Train(clean, CmmConfig{}), test);
  const double noisy_accuracy = HardAccuracy(Train(noisy, CmmConfig{}), test);
  std::printf("accuracy %.3f clean, %.3f with 20%% flipped labels\n", clean_accuracy,
              noisy_accuracy);
  EXPECT_GT(clean_accuracy, 0.95);
  EXPECT_GT(noisy_accuracy, clean_accuracy - 0.05);
}

}  // namespace
}  // namespace relmap::cmm

namespace relmap::cmm {
namespace {

using datasets::Problem;

bool EverySampleInExactlyOneComponentOfItsClass(const CollaborativeMixtureModels& model) {
  std::vector<int> owners(model.dataset().size(), 0);
  for (int label = 0; label < 2; ++label) {
    for (const Component& c : model.components(label)) {
      for (int i : c.indices()) {
        if (model.dataset().label(i) != label) return false;
        ++owners[i];
      }
    }
  }
  return std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; });
}

TEST(Iagmm, SameSeedGivesTheSameModelAndPredictions) {
  const auto data = testing::Problem(Problem::kConcentricRings, 500, 4, 8);
  for (Variant variant : {Variant::kCorrected, Variant::kPaper2018}) {
    CmmConfig config = CmmConfig::ForVariant(variant);
    config.seed = 1234;
    auto a = testing::Train(data, config);
    auto b = testing::Train(data, config);
    EXPECT_EQ(a.component_count(0), b.component_count(0));
    EXPECT_EQ(a.component_count(1), b.component_count(1));
    EXPECT_EQ(a.Snapshot().random_state, b.Snapshot().random_state);
    EXPECT_TRUE((a.Predict(data.features).array() == b.Predict(data.features).array()).all());
  }
}

TEST(Iagmm, SplitsAndMergesWhereTheClassesInterleave) {
  // XOR blobs in 8-d: each class's first component covers blobs of the other
  // class, so it is split; pieces of one class that meet again are merged.
  const auto data = testing::Problem(Problem::kXorBlobs, 800, 8, 3);
  const auto model = testing::Train(data, CmmConfig{});
  EXPECT_GT(model.splits(), 10u);
  EXPECT_GT(model.merges(), 0u);
  EXPECT_GE(model.component_count(0), 4);
  EXPECT_GE(model.component_count(1), 4);
  EXPECT_TRUE(EverySampleInExactlyOneComponentOfItsClass(model));
}

TEST(Iagmm, NeverSplitsSeparatedClasses) {
  // Two far-apart blobs: no component's tolerance ellipsoid reaches the other class.
  datasets::LabelledSamples data;
  data.features.resize(400, 3);
  Random random(2);
  for (int i = 0; i < 400; ++i) {
    const int label = i % 2;
    for (int k = 0; k < 3; ++k) data.features(i, k) = 10.0 * label + random.UniformUnit();
    data.labels.push_back(label);
  }
  const auto model = testing::Train(data, CmmConfig{});
  EXPECT_EQ(model.splits(), 0u);
  EXPECT_EQ(model.merges(), 0u);
  EXPECT_EQ(model.component_count(0), 1);
  EXPECT_EQ(model.component_count(1), 1);
}

TEST(Iagmm, AlphaOneKeepsOneComponentPerClass) {
  CmmConfig config;
  config.alpha = 1.0;
  const auto model = testing::Train(testing::Problem(Problem::kXorBlobs, 500, 2, 4), config);
  EXPECT_EQ(model.component_count(0), 1);
  EXPECT_EQ(model.component_count(1), 1);
}

TEST(Iagmm, AlphaZeroMakesEveryEllipsoidInfiniteWithoutFailing) {
  CmmConfig config;
  config.alpha = 0.0;
  auto model = testing::Train(testing::Problem(Problem::kTwoMoons, 300, 2, 4), config);
  EXPECT_TRUE(model.Predict(Eigen::MatrixXd::Random(10, 2)).allFinite());
  EXPECT_TRUE(std::isfinite(model.LogLikelihood()));
  EXPECT_TRUE(EverySampleInExactlyOneComponentOfItsClass(model));
}

TEST(Iagmm, FewerSamplesThanDimensionsStillPredict) {
  // n <= p: no covariance estimate in 48-d; the prior (corrected) or Σ + λI
  // (corrected_v1) keeps the densities finite. The ridge memorises its 30
  // samples; the prior does not, and may leave one or two on the wrong side.
  const auto data = testing::Problem(Problem::kTwoMoons, 30, 48, 5);
  for (const Variant variant : {Variant::kCorrected, Variant::kCorrectedV1}) {
    const auto model = testing::Train(data, CmmConfig::ForVariant(variant));
    EXPECT_EQ(model.component_count(0) + model.component_count(1), 2);
    const Eigen::VectorXd p = model.Predict(data.features);
    ASSERT_TRUE(p.allFinite());
    int right = 0;
    for (int i = 0; i < p.size(); ++i) right += (p[i] > 0.5) == (data.labels[i] == 1) ? 1 : 0;
    EXPECT_GE(right, variant == Variant::kCorrectedV1 ? 30 : 28) << VariantName(variant);
  }
}

TEST(Iagmm, DuplicateSamplesWithZeroVariance) {
  auto model = CollaborativeMixtureModels::Create(CmmConfig{}, 48).value();
  const Eigen::VectorXd moveable = Eigen::VectorXd::Constant(48, 0.2);
  const Eigen::VectorXd fixed = Eigen::VectorXd::Constant(48, 0.4);
  for (int i = 0; i < 120; ++i) {
    ASSERT_TRUE(model.Add(moveable, 1).ok());
    ASSERT_TRUE(model.Add(fixed, 0).ok());
  }
  Eigen::MatrixXd points(2, 48);
  points.row(0) = moveable.transpose();
  points.row(1) = fixed.transpose();
  const Eigen::VectorXd p = model.Predict(points);
  EXPECT_GT(p[0], 0.99);
  EXPECT_LT(p[1], 0.01);
  EXPECT_TRUE(std::isfinite(model.LogLikelihood()));
}

TEST(Iagmm, OneClassOnly) {
  auto model = CollaborativeMixtureModels::Create(CmmConfig{}, 2).value();
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(model.Add(Eigen::Vector2d(0.01 * i, 0), 1).ok());
  EXPECT_EQ(model.component_count(0), 0);
  EXPECT_GT(model.Predict(Eigen::RowVector2d(0.2, 0))[0], 0.5);
  EXPECT_TRUE(std::isfinite(model.LogLikelihood()));
}

TEST(Iagmm, TenThousandSamples) {
  // Two moons in 2-d: components of thousands of samples that split and merge.
  const auto data = testing::Problem(Problem::kTwoMoons, 10000, 2, 6);
  const auto model = testing::Train(data, CmmConfig{});
  EXPECT_EQ(model.dataset().size(), 10000);
  EXPECT_TRUE(EverySampleInExactlyOneComponentOfItsClass(model));
  EXPECT_TRUE(model.Predict(data.features.topRows(100)).allFinite());
}

TEST(Iagmm, CandidateEvaluationsPerUpdateAreBoundedOnDataThatDoesNotCluster) {
  // Uniform 48-d vectors with fair random labels: every component overlaps the
  // other class, so every update tries to split and merge. An update runs SPLIT or
  // MERGE three times (step 3, then the re-check of each class); each evaluates
  // one split and at most max_merge_candidates merges: 3 · (1 + 4) = 15.
  const CmmConfig config;
  ASSERT_EQ(config.max_merge_candidates, 4);
  auto model = CollaborativeMixtureModels::Create(config, 48).value();
  Random random(5);
  int most = 0;
  for (int i = 0; i < 400; ++i) {
    Eigen::VectorXd x(48);
    for (Eigen::Index d = 0; d < x.size(); ++d) x[d] = random.UniformUnit();
    const auto report = model.Add(x, static_cast<int>(random.UniformIndex(2)));
    ASSERT_TRUE(report.ok());
    most = std::max(most, report->candidates_evaluated);
  }
  EXPECT_LE(most, 3 * (1 + config.max_merge_candidates));
  EXPECT_GT(most, 1);  // the data did make it try several candidates
}

TEST(Iagmm, RejectsBadSamplesAndStaysUnchanged) {
  auto model = CollaborativeMixtureModels::Create(CmmConfig{}, 2).value();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  EXPECT_EQ(model.Add(Eigen::Vector3d(0, 0, 0), 1).status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(model.Add(Eigen::Vector2d(std::nan(""), 0), 1).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(model.Add(Eigen::Vector2d(INFINITY, 0), 0).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(model.Add(Eigen::Vector2d(0, 0), 2).status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(model.dataset().size(), 1);
}

TEST(Iagmm, RejectsAnInvalidConfiguration) {
  CmmConfig config;
  config.alpha = -0.1;
  EXPECT_EQ(CollaborativeMixtureModels::Create(config, 2).status().code(),
            StatusCode::kInvalidArgument);
  config.alpha = 0.25;
  config.regularization = 0.0;
  EXPECT_FALSE(CollaborativeMixtureModels::Create(config, 2).ok());
  EXPECT_FALSE(CollaborativeMixtureModels::Create(CmmConfig{}, 0).ok());
}

}  // namespace
}  // namespace relmap::cmm
