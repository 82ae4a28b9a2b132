// One test per switch of Paper2018Switches: each changes behaviour as docs/method.md
// §3.9 documents, against the corrected model on the same input.
#include <gtest/gtest.h>

#include "cmm/collaborative_mixture_models.h"
#include "support/cmm_training.h"

namespace relmap::cmm {
namespace {

// A component snapshot with the batch mean and scatter of `samples`.
ComponentSnapshot SnapshotOf(const std::vector<int>& samples, const std::vector<double>& features,
                             int p, double weight) {
  Eigen::MatrixXd points(p, static_cast<Eigen::Index>(samples.size()));
  for (std::size_t j = 0; j < samples.size(); ++j) {
    points.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(
        features.data() + static_cast<std::ptrdiff_t>(samples[j]) * p, p);
  }
  const Eigen::VectorXd mean = points.rowwise().mean();
  points.colwise() -= mean;
  const Eigen::MatrixXd scatter = points * points.transpose();
  return {samples,
          {mean.data(), mean.data() + p},
          {scatter.data(), scatter.data() + static_cast<std::ptrdiff_t>(p) * p},
          weight};
}

// Appends `count` 2-d points around (x, y) on a small deterministic spiral.
void AppendBlob(CmmSnapshot& s, double x, double y, int count, std::int8_t label,
                std::vector<int>& indices) {
  for (int i = 0; i < count; ++i) {
    const double r = 0.05 * (1 + i % 7);
    indices.push_back(static_cast<int>(s.labels.size()));
    s.features.push_back(x + r * std::cos(2.4 * i));
    s.features.push_back(y + r * std::sin(2.4 * i));
    s.labels.push_back(label);
  }
}

// corrected_v1 with one switch of the 2018 code turned on.
CmmConfig With(void (*turn_on)(Paper2018Switches&)) {
  CmmConfig config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  turn_on(config.switches);
  return config;
}

Eigen::MatrixXd Row(double x, double y) { return Eigen::RowVector2d(x, y); }

TEST(Paper2018Preset, TurnsOnTheFiveDefectSwitchesOnly) {
  const CmmConfig paper = CmmConfig::ForVariant(Variant::kPaper2018);
  EXPECT_TRUE(paper.switches.pseudo_density && paper.switches.first_sample_mean &&
              paper.switches.stale_weights && paper.switches.nearest_candidate_only &&
              paper.switches.truncated_recheck);
  EXPECT_FALSE(paper.switches.skip_likelihood_check);
  const Paper2018Switches& corrected = CmmConfig::ForVariant(Variant::kCorrected).switches;
  EXPECT_FALSE(corrected.pseudo_density || corrected.first_sample_mean || corrected.stale_weights ||
               corrected.nearest_candidate_only || corrected.truncated_recheck ||
               corrected.skip_likelihood_check);
}

TEST(Paper2018Switches, PseudoDensityMakesSmallComponentsHitsOfDensityOne) {
  // Three moveable samples: a "hit" component of peak 1 at their mean (2, 0), so
  // P = (1 + 1)/(2 + 1) = 2/3 there and exactly 1/2 beyond ‖x − μ‖² = 1e-4.
  auto paper = CollaborativeMixtureModels::Create(
                   With([](Paper2018Switches& s) { s.pseudo_density = true; }), 2)
                   .value();
  auto corrected =
      CollaborativeMixtureModels::Create(CmmConfig::ForVariant(Variant::kCorrectedV1), 2).value();
  for (double x : {0.0, 2.0, 4.0}) {
    ASSERT_TRUE(paper.Add(Eigen::Vector2d(x, 0), 1).ok());
    ASSERT_TRUE(corrected.Add(Eigen::Vector2d(x, 0), 1).ok());
  }
  EXPECT_DOUBLE_EQ(paper.Predict(Row(2, 0))[0], 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(paper.Predict(Row(2.5, 0))[0], 0.5);
  EXPECT_GT(corrected.Predict(Row(2.5, 0))[0], 0.5);
  EXPECT_NE(corrected.Predict(Row(2, 0))[0], 2.0 / 3.0);
}

TEST(Paper2018Switches, FirstSampleMeanCentresSmallComponentsOnTheirFirstSample) {
  auto paper = CollaborativeMixtureModels::Create(
                   With([](Paper2018Switches& s) { s.first_sample_mean = true; }), 2)
                   .value();
  auto corrected =
      CollaborativeMixtureModels::Create(CmmConfig::ForVariant(Variant::kCorrectedV1), 2).value();
  for (double x : {0.0, 2.0, 4.0}) {
    ASSERT_TRUE(paper.Add(Eigen::Vector2d(x, 0), 1).ok());
    ASSERT_TRUE(corrected.Add(Eigen::Vector2d(x, 0), 1).ok());
  }
  EXPECT_EQ(paper.components(1)[0].centre(), Eigen::Vector2d(0, 0));
  EXPECT_EQ(corrected.components(1)[0].centre(), Eigen::Vector2d(2, 0));
  EXPECT_EQ(paper.Evaluate(Row(0, 0)).nearest_squared_mahalanobis[0], 0.0);
}

TEST(Paper2018Switches, StaleWeightsAreNotRefreshedAfterAnAppend) {
  // Two one-sample moveable components of weight ½; a third sample joins the
  // first: corrected weights become 2/3 and 1/3, stale ones stay ½ and ½.
  CmmSnapshot snapshot;
  snapshot.config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  snapshot.dimension = 2;
  snapshot.features = {0, 0, 10, 0};
  snapshot.labels = {1, 1};
  snapshot.components[1] = {SnapshotOf({0}, snapshot.features, 2, 0.5),
                            SnapshotOf({1}, snapshot.features, 2, 0.5)};
  auto corrected = CollaborativeMixtureModels::Restore(snapshot).value();
  snapshot.config.switches.stale_weights = true;
  auto paper = CollaborativeMixtureModels::Restore(snapshot).value();
  ASSERT_TRUE(corrected.Add(Eigen::Vector2d(0.1, 0), 1).ok());
  ASSERT_TRUE(paper.Add(Eigen::Vector2d(0.1, 0), 1).ok());
  EXPECT_DOUBLE_EQ(corrected.components(1)[0].weight(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(paper.components(1)[0].weight(), 0.5);
  EXPECT_DOUBLE_EQ(paper.components(1)[1].weight(), 0.5);
}

TEST(Paper2018Switches, NearestCandidateOnlyNeverMergesComponentsUnderFiveSamples) {
  // Class 0: a 30-sample blob A at the origin and a 3-sample component B inside
  // it. A new sample joins A, whose MERGE finds B inside its tolerance
  // ellipsoid. The likelihood check is off so that only the candidate rule acts.
  CmmSnapshot snapshot;
  snapshot.config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  snapshot.dimension = 2;
  std::vector<int> a;
  std::vector<int> b;
  AppendBlob(snapshot, 0, 0, 30, 0, a);
  AppendBlob(snapshot, 0.02, 0.01, 3, 0, b);
  snapshot.components[0] = {SnapshotOf(a, snapshot.features, 2, 30.0 / 33),
                            SnapshotOf(b, snapshot.features, 2, 3.0 / 33)};
  snapshot.config.switches.skip_likelihood_check = true;
  auto corrected = CollaborativeMixtureModels::Restore(snapshot).value();
  snapshot.config.switches.nearest_candidate_only = true;
  auto paper = CollaborativeMixtureModels::Restore(snapshot).value();

  const auto corrected_report = corrected.Add(Eigen::Vector2d(-0.2, -0.2), 0);
  const auto paper_report = paper.Add(Eigen::Vector2d(-0.2, -0.2), 0);
  ASSERT_EQ(corrected_report->component, 0);
  ASSERT_EQ(paper_report->component, 0);
  EXPECT_EQ(corrected.component_count(0), 1);
  EXPECT_EQ(paper.component_count(0), 2);
}

TEST(Paper2018Switches, TruncatedRecheckStopsAtAClassWithOneComponent) {
  // Class 0 has one component, class 1 two overlapping blobs. A class-0 sample
  // triggers the re-check: corrected visits class 1 and merges its blobs; the
  // 2018 code stops at class 0. (Likelihood check off: only the re-check acts.)
  CmmSnapshot snapshot;
  snapshot.config = CmmConfig::ForVariant(Variant::kCorrectedV1);
  snapshot.dimension = 2;
  std::vector<int> lone;
  std::vector<int> a;
  std::vector<int> b;
  AppendBlob(snapshot, 10, 10, 1, 0, lone);
  AppendBlob(snapshot, 0, 0, 30, 1, a);
  AppendBlob(snapshot, 0.05, 0, 30, 1, b);
  snapshot.components[0] = {SnapshotOf(lone, snapshot.features, 2, 1.0)};
  snapshot.components[1] = {SnapshotOf(a, snapshot.features, 2, 0.5),
                            SnapshotOf(b, snapshot.features, 2, 0.5)};
  snapshot.config.switches.skip_likelihood_check = true;
  auto corrected = CollaborativeMixtureModels::Restore(snapshot).value();
  snapshot.config.switches.truncated_recheck = true;
  auto paper = CollaborativeMixtureModels::Restore(snapshot).value();

  ASSERT_TRUE(corrected.Add(Eigen::Vector2d(10, 10.01), 0).ok());
  ASSERT_TRUE(paper.Add(Eigen::Vector2d(10, 10.01), 0).ok());
  EXPECT_EQ(corrected.component_count(1), 1);
  EXPECT_EQ(paper.component_count(1), 2);
}

TEST(Paper2018Switches, SkipLikelihoodCheckAcceptsWithoutEvaluatingCandidates) {
  const auto data = testing::Problem(datasets::Problem::kXorBlobs, 400, 2, 31);
  auto checked =
      CollaborativeMixtureModels::Create(CmmConfig::ForVariant(Variant::kCorrectedV1), 2).value();
  auto unchecked = CollaborativeMixtureModels::Create(
                       With([](Paper2018Switches& s) { s.skip_likelihood_check = true; }), 2)
                       .value();
  int checked_evaluations = 0;
  int unchecked_evaluations = 0;
  for (int i = 0; i < 400; ++i) {
    checked_evaluations +=
        checked.Add(data.features.row(i).transpose(), data.labels[i])->candidates_evaluated;
    unchecked_evaluations +=
        unchecked.Add(data.features.row(i).transpose(), data.labels[i])->candidates_evaluated;
  }
  EXPECT_GT(checked_evaluations, 0);
  EXPECT_EQ(unchecked_evaluations, 0);
  // Without the check, every intersecting candidate is accepted: more changes.
  EXPECT_GT(unchecked.splits() + unchecked.merges(), checked.splits() + checked.merges());
}

}  // namespace
}  // namespace relmap::cmm
