// Acceptance of the simulator (issue 5): a short oracle run on the paper's
// MoveableBalls scene, against a real relmap-server, learns what moves.
#include <gtest/gtest.h>

#include "experiment.h"
#include "integration/test_support.h"
#include "local_server.h"
#include "scene_loading.h"

namespace relmap::sim {
namespace {

TEST(MoveableBalls, SixtyOracleIterationsReachAnAccuracyOfNinetyPercent) {
  relmap::testing::TemporaryDirectory out;
  client::LocalServerOptions server_options;
  server_options.log_path = out.path() + "/server.log";
  StatusOr<std::unique_ptr<client::LocalServer>> server =
      client::LocalServer::Start(RELMAP_SERVER_BINARY, server_options);
  ASSERT_TRUE(server.ok()) << server.status().message();
  client::RelevanceClient client((*server)->address());

  ExperimentOptions options;
  options.scene = "MoveableBalls";
  options.out = out.path();
  options.iterations = 60;
  options.replications = 1;
  options.seed = 1;
  options.snapshots = {};
  StatusOr<ExperimentRun> run =
      RunExperiment(options, LoadOdeScene, client, (*server)->address(), true, nullptr);
  ASSERT_TRUE(run.ok()) << run.status().message();
  const ReplicationResult& result = run->replications.at(0);
  ASSERT_EQ(result.error, "");
  ASSERT_EQ(result.iterations.size(), 60u);
  const IterationRecord& last = result.iterations.back();
  ASSERT_TRUE(last.thresholded.accuracy.has_value());
  EXPECT_GE(*last.thresholded.accuracy, 0.9);
}

}  // namespace
}  // namespace relmap::sim
