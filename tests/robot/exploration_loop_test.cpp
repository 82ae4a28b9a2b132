// relmap-robot's loop through a real relmap-server, with the analytic test scene as
// the robot: learning, the workspace box, failing drivers (exec and tcp-json), dry
// runs, restarts, and record → replay.
#include "exploration_loop.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "exec_driver.h"
#include "fake_controller.h"
#include "integration/suite_server.h"
#include "integration/test_support.h"
#include "ode_scene.h"
#include "replay.h"
#include "run_record.h"
#include "sim/analytic_scene.h"
#include "sim_robot.h"
#include "tcp_json_driver.h"

namespace relmap::robot {
namespace {

namespace fs = std::filesystem;

// A driver that counts its pushes and answers with `outcome`.
class FakeDriver final : public PusherDriver {
 public:
  explicit FakeDriver(StatusOr<PushOutcome> outcome) : outcome_(std::move(outcome)) {}
  StatusOr<PushOutcome> Push(const DriverRequest&) override {
    ++pushes;
    return outcome_;
  }
  int pushes = 0;

 private:
  StatusOr<PushOutcome> outcome_;
};

// A driver during whose push the operator presses Ctrl-C.
class InterruptedDriver final : public PusherDriver {
 public:
  explicit InterruptedDriver(std::atomic<bool>& stop) : stop_(stop) {}
  StatusOr<PushOutcome> Push(const DriverRequest&) override {
    stop_.store(true);
    return PushOutcome{PushResult::kDone, v1::LABEL_MOVEABLE, ""};
  }

 private:
  std::atomic<bool>& stop_;
};

class ExplorationLoopTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    client::LocalServerOptions options;
    options.memory_only = true;
    options.log_path =
        ::testing::TempDir() + "/relmap_robot_server_" + std::to_string(::getpid()) + ".log";
    suite_.Start(options);
  }
  static void TearDownTestSuite() { suite_.Stop(); }

  // Recorded into run_dir_; a 160×120 camera sees 1/16 of a Kinect's points per area,
  // hence the change detector's 3 neighbours instead of 20 (as relmap-sim scales it).
  RobotConfig Config(unsigned max_pushes) const {
    RobotConfig config;
    config.mutable_source()->mutable_sim()->set_scene("AnalyticScene");
    config.mutable_driver()->mutable_sim();
    config.mutable_session()->set_seed(11);
    config.mutable_session()->mutable_change_detector()->set_ror_min_neighbours(3);
    config.set_max_pushes(max_pushes);
    config.set_max_iterations(4 * max_pushes);
    config.set_retries(2);
    config.set_run_dir(run_dir_.path() + "/run");
    return config;
  }

  // Runs `config` with `driver` on the scene; the session it used.
  StatusOr<RunSummary> Run(const RobotConfig& config, PusherDriver& driver,
                           client::SessionHandle* session = nullptr,
                           sim::SimulatedScene* scene = nullptr) {
    SimSource source(scene != nullptr ? *scene : scene_);
    ExplorationLoop loop(config, suite_.client(), source, driver, nullptr, nullptr);
    if (Status status = loop.Start(); !status.ok()) return status;
    if (session != nullptr) *session = loop.session();
    return loop.Run();
  }

  static v1::SessionState Export(const client::SessionHandle& session) {
    v1::ExportSessionResponse exported;
    EXPECT_TRUE(suite_.client().ExportSession(session, &exported).ok());
    return exported.state();
  }

  std::string IterationFile(int iteration, const std::string& name) const {
    return IterationDirectory(run_dir_.path() + "/run", iteration) + "/" + name;
  }
  IterationStatus StatusOf(int iteration) const {
    IterationStatus status;
    EXPECT_TRUE(ReadJson(IterationFile(iteration, "status.json"), &status).ok());
    return status;
  }

  // Iteration 1 failed in all three attempts (the last one's error recorded) and posted
  // nothing; iteration 2 posted `label`, the session's only sample.
  void ExpectFirstIterationFailedAndSecondPosted(const RunSummary& summary,
                                                 const client::SessionHandle& session,
                                                 v1::Label label) const {
    EXPECT_EQ(StatusOf(1).state(), "failed");
    EXPECT_EQ(StatusOf(1).attempts(), 3u);
    EXPECT_FALSE(fs::exists(IterationFile(1, "label.json")));
    DriverResult last_attempt;
    ASSERT_TRUE(ReadJson(IterationFile(1, "driver.json"), &last_attempt).ok());
    EXPECT_EQ(last_attempt.result(), "error");
    EXPECT_EQ(StatusOf(2).state(), "posted");
    EXPECT_EQ(summary.failed, 1);
    EXPECT_EQ(summary.posted, 1);
    const v1::SessionState state = Export(session);
    ASSERT_EQ(state.samples_size(), 1);
    EXPECT_EQ(state.samples(0).label(), label);
  }

  // What the posted iterations taught the session: each target, and the other parts of its
  // object the change detector saw move (label.json's moved_learned, docs/method.md §4.5).
  int LearnedSamples(const RunSummary& summary) const {
    int learned = 0;
    for (int i = 1; i <= summary.iterations; ++i) {
      v1::PostOutcomeResponse posted;
      if (ReadJson(IterationFile(i, "label.json"), &posted).ok()) {
        learned += 1 + static_cast<int>(posted.moved_learned());
      }
    }
    return learned;
  }

  static inline relmap::testing::SuiteServer suite_;
  relmap::testing::TemporaryDirectory run_dir_;
  sim::testing::AnalyticScene scene_{3};
};

TEST_F(ExplorationLoopTest, TheSimulatorPushesAndTheServerLearnsEveryOutcome) {
  SimDriver driver(scene_, 5);
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(Config(3), driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(summary->pushes, 3);
  EXPECT_EQ(summary->posted + summary->failed, summary->iterations);
  EXPECT_EQ(Export(session).samples_size(), LearnedSamples(*summary));
  ASSERT_GE(summary->posted, 1);
  for (const char* name : {"before.cloud", "maps.json", "target.json", "driver.json", "after.cloud",
                           "label.json", "truth.json", "status.json"}) {
    EXPECT_TRUE(fs::is_regular_file(IterationFile(1, name))) << name;
  }
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(ReadJson(IterationFile(1, "maps.json"), &maps).ok());
  EXPECT_GT(maps.supervoxels_size(), 0);
  EXPECT_EQ(maps.point_labels_size(), 0);
}

TEST_F(ExplorationLoopTest, TheOdeSimulatorStandsInForTheRobot) {
  StatusOr<std::unique_ptr<sim::OdeScene>> balls = sim::OdeScene::Load("MoveableBalls", 3);
  ASSERT_TRUE(balls.ok()) << balls.status().message();
  (*balls)->SetImageSize(160, 120);
  SimDriver driver(**balls, 3);
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(Config(3), driver, &session, balls->get());
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(summary->pushes, 3);
  EXPECT_GE(summary->posted, 1);
  EXPECT_EQ(Export(session).samples_size(), LearnedSamples(*summary));
}

TEST_F(ExplorationLoopTest, ATargetOutsideTheWorkspaceIsNeverSentToTheDriver) {
  RobotConfig config = Config(2);
  v1::WorkspaceBox* far_away = config.mutable_workspace();
  far_away->set_min_x(-1);
  far_away->set_max_x(1);
  far_away->set_min_y(-1);
  far_away->set_max_y(1);
  far_away->set_min_z(5);  // the table is 1 m away
  far_away->set_max_z(6);
  config.set_max_iterations(3);
  FakeDriver driver(PushOutcome{PushResult::kDone, v1::LABEL_MOVEABLE, ""});
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(config, driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(driver.pushes, 0);
  EXPECT_EQ(summary->skipped, 3);
  EXPECT_EQ(Export(session).samples_size(), 0);
  EXPECT_EQ(StatusOf(1).state(), "skipped");
}

TEST_F(ExplorationLoopTest, AFailingPushIsRetriedWithFreshFramesAndNothingIsPosted) {
  // A driver that crashes every time: one iteration, three attempts (two retries).
  const std::string script = run_dir_.path() + "/crash.sh";
  std::ofstream(script) << "#!/bin/sh\nkill -KILL $$\n";
  ::chmod(script.c_str(), 0755);
  ExecDriver driver({script}, std::chrono::milliseconds(5000));
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(Config(3), driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(summary->iterations, 1);
  EXPECT_EQ(summary->failed, 1);
  EXPECT_EQ(StatusOf(1).attempts(), 3u);
  EXPECT_EQ(Export(session).samples_size(), 0);
  EXPECT_FALSE(fs::exists(IterationFile(1, "label.json")));
  // Three ComputeMaps, one per attempt.
  v1::GetSessionResponse got;
  ASSERT_TRUE(suite_.client().GetSession(session, &got).ok());
  EXPECT_EQ(got.stats().frames(), 3u);
}

TEST_F(ExplorationLoopTest,
       AControllerThatAnswersGarbageFallsSilentOrHangsUpPostsNothingAndTheLoopGoesOn) {
  // Iteration 1's three attempts (two retries): garbage, silence past the reply
  // timeout, a hang-up. From then on the controller pushes and reports "moved".
  FakeController controller([](int request, const std::string&) -> std::string {
    if (request == 1) return "pushed it, boss";
    if (request == 2) return "";
    if (request == 3) return FakeController::kHangUp;
    return R"({"result": "done", "label": "moved"})";
  });
  TcpJsonDriver driver(controller.address(), std::chrono::milliseconds(2000),
                       std::chrono::milliseconds(300));
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(Config(4), driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  ExpectFirstIterationFailedAndSecondPosted(*summary, session, v1::LABEL_MOVEABLE);
}

TEST_F(ExplorationLoopTest,
       AnExecDriverThatAnswersGarbageHangsOrCrashesPostsNothingAndTheLoopGoesOn) {
  // The script counts its runs in a file: garbage, a hang past the timeout, a crash,
  // then pushes with its own label "still".
  const std::string count = run_dir_.path() + "/runs";
  const std::string script = run_dir_.path() + "/driver.sh";
  std::ofstream(script) << "#!/bin/sh\ncat > /dev/null\ncount=" << count << "\n"
                        << R"sh(n=$(($(cat "$count" 2>/dev/null || echo 0) + 1)); echo $n > "$count"
case $n in
  1) echo 'pushed it, boss' ;;
  2) sleep 30 ;;
  3) kill -SEGV $$ ;;
  *) echo '{"result": "done", "label": "still"}' ;;
esac
)sh";
  ::chmod(script.c_str(), 0755);
  ExecDriver driver({script}, std::chrono::milliseconds(300));
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(Config(4), driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  ExpectFirstIterationFailedAndSecondPosted(*summary, session, v1::LABEL_NOT_MOVEABLE);
}

TEST_F(ExplorationLoopTest, TheDriversOwnLabelIsPostedWithoutAnAfterCloud) {
  FakeDriver driver(PushOutcome{PushResult::kDone, v1::LABEL_MOVEABLE, "felt it move"});
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(Config(2), driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(summary->posted, 2);
  const v1::SessionState state = Export(session);
  ASSERT_EQ(state.samples_size(), 2);
  for (const v1::LabelledFeature& sample : state.samples()) {
    EXPECT_EQ(sample.label(), v1::LABEL_MOVEABLE);
  }
  EXPECT_FALSE(fs::exists(IterationFile(1, "after.cloud")));
}

TEST_F(ExplorationLoopTest, AStopDuringAPushPostsThatPushAndEndsTheRun) {
  std::atomic<bool> stop{false};
  InterruptedDriver driver(stop);
  SimSource source(scene_);
  const RobotConfig config = Config(5);
  ExplorationLoop loop(config, suite_.client(), source, driver, &stop, nullptr);
  ASSERT_TRUE(loop.Start().ok());
  StatusOr<RunSummary> summary = loop.Run();
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_TRUE(summary->stopped);
  EXPECT_EQ(summary->pushes, 1);
  EXPECT_EQ(summary->posted, 1);
  EXPECT_EQ(Export(loop.session()).samples_size(), 1);
}

TEST_F(ExplorationLoopTest, ADryRunPushesAndPostsNothing) {
  RobotConfig config = Config(2);
  config.set_dry_run(true);
  FakeDriver driver(PushOutcome{PushResult::kDone, v1::LABEL_MOVEABLE, ""});
  client::SessionHandle session;
  StatusOr<RunSummary> summary = Run(config, driver, &session);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(summary->dry_run, 2);
  EXPECT_EQ(driver.pushes, 0);
  EXPECT_EQ(Export(session).samples_size(), 0);
}

TEST_F(ExplorationLoopTest, ARestartResumesTheSessionAndNeverPostsAnIterationTwice) {
  FakeDriver driver(PushOutcome{PushResult::kDone, v1::LABEL_NOT_MOVEABLE, ""});
  client::SessionHandle first;
  ASSERT_TRUE(Run(Config(2), driver, &first).ok());
  // A crash after iteration 2's post, before its status was written: the restart redoes
  // iteration 2 under the same request id, which the server has already answered.
  fs::remove(IterationFile(2, "status.json"));
  client::SessionHandle second;
  StatusOr<RunSummary> summary = Run(Config(1), driver, &second);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  EXPECT_EQ(second.id, first.id);
  EXPECT_EQ(summary->posted, 1);
  EXPECT_EQ(Export(first).samples_size(), 2);
  EXPECT_FALSE(fs::exists(IterationDirectory(run_dir_.path() + "/run", 3)));
}

TEST_F(ExplorationLoopTest, AReplayedRunLearnsTheSameSamples) {
  SimDriver driver(scene_, 8);
  client::SessionHandle recorded;
  StatusOr<RunSummary> summary = Run(Config(4), driver, &recorded);
  ASSERT_TRUE(summary.ok()) << summary.status().message();
  ASSERT_GE(summary->posted, 2);

  StatusOr<ReplayResult> replayed = ReplayRun(run_dir_.path() + "/run", suite_.client());
  ASSERT_TRUE(replayed.ok()) << replayed.status().message();
  ASSERT_EQ(static_cast<int>(replayed->iterations.size()), summary->posted);
  for (const ReplayedIteration& iteration : replayed->iterations) {
    EXPECT_TRUE(iteration.accuracy.has_value()) << "the simulator records ground truth";
  }
  const v1::SessionState original = Export(recorded);
  const v1::SessionState replay = Export(replayed->session);
  ASSERT_EQ(replay.samples_size(), original.samples_size());
  for (int i = 0; i < original.samples_size(); ++i) {
    EXPECT_EQ(replay.samples(i).SerializeAsString(), original.samples(i).SerializeAsString())
        << "sample " << i;
  }
}

}  // namespace
}  // namespace relmap::robot
