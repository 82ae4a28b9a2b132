// The runner against a real relmap-server process, on the analytic test scene: the
// files a run writes, a learning oracle run, and the physical mode's push and
// change-detector labels.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "curves.h"
#include "experiment.h"
#include "integration/suite_server.h"
#include "integration/test_support.h"
#include "sim/analytic_scene.h"

namespace relmap::sim {
namespace {

// One server for the whole suite: every replication has its own session anyway.
class RunnerEndToEnd : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    log_ =
        ::testing::TempDir() + "/relmap_sim_runner_server_" + std::to_string(::getpid()) + ".log";
    client::LocalServerOptions server_options;
    server_options.log_path = log_;
    suite_.Start(server_options);
  }
  static void TearDownTestSuite() { suite_.Stop(); }

  // Runs `options` on analytic scenes into `out_`.
  ExperimentRun Run(ExperimentOptions options, std::uint32_t width = 160,
                    std::uint32_t height = 120) {
    options.scene = "AnalyticScene";
    options.out = out_.path();
    const SceneFactory analytic = [width, height](const std::string&, std::uint64_t seed) {
      return StatusOr<std::unique_ptr<SimulatedScene>>(
          std::make_unique<testing::AnalyticScene>(seed, width, height));
    };
    StatusOr<ExperimentRun> run =
        RunExperiment(options, analytic, suite_.client(), suite_.server().address(), true, nullptr);
    EXPECT_TRUE(run.ok()) << run.status().message();
    if (!run.ok()) return {};
    for (const ReplicationResult& r : run->replications) EXPECT_EQ(r.error, "");
    return std::move(*run);
  }

  std::string Read(const std::string& name) const {
    std::ifstream in(out_.path() + "/" + name);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  bool Exists(const std::string& name) const {
    return std::filesystem::is_regular_file(out_.path() + "/" + name);
  }

  static inline std::string log_;
  static inline relmap::testing::SuiteServer suite_;
  relmap::testing::TemporaryDirectory out_;
};

TEST_F(RunnerEndToEnd, ATinyRunWritesItsCsvsSummarySnapshotsAndPlots) {
  ExperimentOptions options;
  options.iterations = 3;
  options.replications = 2;
  options.seed = 5;
  options.snapshots = {1, 3};
  const ExperimentRun run = Run(options);
  ASSERT_EQ(run.replications.size(), 2u);
  for (int r = 0; r < 2; ++r) {
    const std::string csv = Read("replication-" + std::to_string(r) + ".csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n')), kIterationCsvHeader);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;  // header + 3 rows
    EXPECT_EQ(run.replications[static_cast<std::size_t>(r)].seed, 5u + r);
    for (const char* map : {"relevance-", "choice-"}) {
      for (const int iteration : {1, 3}) {
        EXPECT_TRUE(Exists(map + std::to_string(r) + "-" + std::to_string(iteration) + ".png"));
      }
      EXPECT_FALSE(Exists(map + std::to_string(r) + "-2.png"));
    }
  }
  for (const char* plot : {"accuracy", "precision", "recall", "samples", "components"}) {
    EXPECT_TRUE(Exists(std::string(plot) + ".png")) << plot;
  }
  const std::string summary = Read("summary.json");
  EXPECT_NE(summary.find("\"scene\": \"AnalyticScene\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"replications_counted\": 2"), std::string::npos);
  EXPECT_NE(summary.find("\"session_id\": \"" + run.replications[1].session_id + "\""),
            std::string::npos);
  // Oracle labels are the ground truth: three samples, none mislabelled.
  for (const ReplicationResult& r : run.replications) {
    const IterationRecord& last = r.iterations.back();
    EXPECT_EQ(last.model.moveable_samples + last.model.non_moveable_samples, 3u);
    EXPECT_EQ(last.mislabelled, 0u);
  }
}

TEST_F(RunnerEndToEnd, TwentyOracleIterationsLearnWhatMoves) {
  ExperimentOptions options;
  options.iterations = 20;
  options.replications = 2;
  options.snapshots = {};
  const ExperimentRun run = Run(options);
  for (const ReplicationResult& r : run.replications) {
    ASSERT_EQ(r.iterations.size(), 20u);
    const IterationRecord& first = r.iterations.front();
    const IterationRecord& last = r.iterations.back();
    // Untrained, every relevance is 0.5: the thresholded-soft accuracy is 0.25 (§6).
    EXPECT_DOUBLE_EQ(*first.thresholded.accuracy, 0.25);
    // Measured over seeds 1..16: 0.935 to 1.000 after 20 iterations (mean 0.97).
    EXPECT_GT(*last.thresholded.accuracy, 0.85) << "replication " << r.replication;
  }
}

// --labels moved names a target's body only when the target is moveable: every
// not-moveable sample is a target, and the bodies' other supervoxels add moveable ones.
TEST_F(RunnerEndToEnd, MovedLabelsAddTheBodyOfAMoveableTargetOnly) {
  ExperimentOptions options;
  options.iterations = 12;
  options.labels = LabelScope::kMoved;
  options.snapshots = {};
  const ExperimentRun run = Run(options);
  ASSERT_EQ(run.replications.size(), 1u);
  std::uint64_t moveable_pushes = 0;
  std::uint64_t still_pushes = 0;
  for (const IterationRecord& i : run.replications[0].iterations) {
    if (!i.truth) continue;
    ++(*i.truth ? moveable_pushes : still_pushes);
  }
  ASSERT_GT(moveable_pushes, 0u);
  ASSERT_GT(still_pushes, 0u);
  const IterationRecord& last = run.replications[0].iterations.back();
  EXPECT_EQ(last.model.non_moveable_samples, still_pushes);
  EXPECT_EQ(last.model.moveable_samples, moveable_pushes + last.moved_learned);
  EXPECT_GT(last.moved_learned, 0u);
}

TEST_F(RunnerEndToEnd, ThePhysicalModePushesAndLearnsTheChangeDetectorsLabels) {
  ExperimentOptions options;
  options.mode = LabellingMode::kPhysical;
  options.iterations = 8;
  options.replications = 1;
  options.snapshots = {};
  // The change detector's outlier filters (radius 1 cm, at least 20 neighbours) want
  // a Kinect's point density: at 160×120 they leave nothing (every push reads "not
  // moved"), at 320×240 they miss most moves; 640×480 is what they were tuned for.
  const ExperimentRun run = Run(options, 640, 480);
  ASSERT_EQ(run.replications.size(), 1u);
  std::uint64_t mislabelled = 0, detected_moves = 0;
  for (const IterationRecord& i : run.replications[0].iterations) {
    ASSERT_TRUE(i.target.has_value());
    ASSERT_TRUE(i.push.has_value());
    EXPECT_TRUE(i.push->executed);
    ASSERT_TRUE(i.label.has_value() && i.truth.has_value());
    if (*i.label != *i.truth) ++mislabelled;
    if (*i.label) ++detected_moves;
    EXPECT_EQ(i.mislabelled, mislabelled);
    EXPECT_GT(i.timings.push_ms, 0.0);
  }
  // Measured: 4 of the 5 pushes that moved a body were seen as moves.
  EXPECT_GT(detected_moves, 0u);
  const std::string csv = Read("replication-0.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
}

TEST_F(RunnerEndToEnd, RandomSamplingPushesUsableSupervoxels) {
  ExperimentOptions options;
  options.iterations = 4;
  options.replications = 1;
  options.sampling = TargetSampling::kRandom;
  options.snapshots = {};
  const ExperimentRun run = Run(options);
  ASSERT_EQ(run.replications.size(), 1u);
  for (const IterationRecord& i : run.replications[0].iterations) {
    EXPECT_TRUE(i.target.has_value()) << i.iteration;
  }
}

}  // namespace
}  // namespace relmap::sim
