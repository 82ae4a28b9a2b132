// `relmap-sim run`'s flags: defaults, and a clear INVALID_ARGUMENT for each misuse.
#include "experiment_options.h"

#include <gtest/gtest.h>

#include <vector>

namespace relmap::sim {
namespace {

StatusOr<ExperimentOptions> Parse(std::vector<const char*> words) {
  words.insert(words.begin(), "run");
  return ParseExperimentOptions(static_cast<int>(words.size()), words.data(), 1);
}

TEST(ExperimentOptions, DefaultsAreOneOracleReplicationOfTheChoiceMapsTargets) {
  const StatusOr<ExperimentOptions> options = Parse({"--scene", "MoveableBalls", "--out", "d"});
  ASSERT_TRUE(options.ok()) << options.status().message();
  EXPECT_EQ(options->mode, LabellingMode::kOracle);
  EXPECT_EQ(options->sampling, TargetSampling::kChoice);
  EXPECT_EQ(options->variant, v1::CLASSIFIER_VARIANT_CORRECTED);
  EXPECT_FALSE(options->alpha.has_value());
  EXPECT_EQ(options->replications, 1);
  EXPECT_EQ(options->parallel, 2);
  EXPECT_TRUE(options->server.empty());
  // 1, 10, 100 below the 100 iterations, then the last: 100 once.
  EXPECT_EQ(options->snapshots, (std::vector<int>{1, 10, 100}));
}

TEST(ExperimentOptions, ReadsEveryFlag) {
  const StatusOr<ExperimentOptions> options = Parse(
      {"--scene",      "s.yaml", "--out",          "d",         "--mode",      "physical",
       "--iterations", "250",    "--replications", "10",        "--seed",      "7",
       "--server",     "host:1", "--variant",      "paper2018", "--alpha",     "0.5",
       "--sampling",   "random", "--parallel",     "4",         "--snapshots", "200,1,50,50"});
  ASSERT_TRUE(options.ok()) << options.status().message();
  EXPECT_EQ(options->mode, LabellingMode::kPhysical);
  EXPECT_EQ(options->iterations, 250);
  EXPECT_EQ(options->replications, 10);
  EXPECT_EQ(options->seed, 7u);
  EXPECT_EQ(options->server, "host:1");
  EXPECT_EQ(options->variant, v1::CLASSIFIER_VARIANT_PAPER2018);
  EXPECT_EQ(options->alpha, 0.5);
  EXPECT_EQ(options->sampling, TargetSampling::kRandom);
  EXPECT_EQ(options->parallel, 4);
  EXPECT_EQ(options->snapshots, (std::vector<int>{1, 50, 200}));  // sorted, once each
}

TEST(ExperimentOptions, DefaultSnapshotsEndAtTheLastIteration) {
  EXPECT_EQ(Parse({"--scene", "s", "--out", "d", "--iterations", "1000"})->snapshots,
            (std::vector<int>{1, 10, 100, 1000}));
  EXPECT_EQ(Parse({"--scene", "s", "--out", "d", "--iterations", "20"})->snapshots,
            (std::vector<int>{1, 10, 20}));
  EXPECT_TRUE(Parse({"--scene", "s", "--out", "d", "--snapshots", "none"})->snapshots.empty());
}

TEST(ExperimentOptions, LabelsAreTheTargetTheObjectOrWhatMoved) {
  EXPECT_EQ(Parse({"--scene", "s", "--out", "d"})->labels, LabelScope::kTarget);
  for (const auto& [word, scope] :
       {std::pair{"target", LabelScope::kTarget}, std::pair{"object", LabelScope::kObject},
        std::pair{"moved", LabelScope::kMoved}}) {
    const StatusOr<ExperimentOptions> options =
        Parse({"--scene", "s", "--out", "d", "--labels", word});
    ASSERT_TRUE(options.ok()) << options.status().message();
    EXPECT_EQ(options->labels, scope) << word;
    EXPECT_STREQ(LabelScopeName(scope), word);
  }
}

TEST(ExperimentOptions, MisuseIsAnInvalidArgumentNamingTheFlag) {
  const std::vector<std::pair<std::vector<const char*>, std::string>> cases = {
      {{"--out", "d"}, "--scene"},
      {{"--scene", "s"}, "--out"},
      {{"--scene", "s", "--out", "d", "--mode", "push"}, "--mode"},
      {{"--scene", "s", "--out", "d", "--iterations", "0"}, "--iterations"},
      {{"--scene", "s", "--out", "d", "--iterations", "1x"}, "--iterations"},
      {{"--scene", "s", "--out", "d", "--alpha", "1.5"}, "--alpha"},
      {{"--scene", "s", "--out", "d", "--labels", "body"}, "--labels"},
      {{"--scene", "s", "--out", "d", "--snapshots", "1,200"}, "--snapshots"},
      {{"--scene", "s", "--out", "d", "--colour", "red"}, "--colour"},
      {{"--scene", "s", "--out"}, "--out"},
      {{"--scene", "s", "--out", "d", "--server", "a:1", "--server-binary", "b"}, "--server"},
  };
  for (const auto& [words, flag] : cases) {
    const StatusOr<ExperimentOptions> options = Parse(words);
    ASSERT_FALSE(options.ok()) << flag;
    EXPECT_EQ(options.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(options.status().message().find(flag), std::string::npos)
        << options.status().message();
  }
}

TEST(ExperimentOptions, TheChangeDetectorsNeighbourCountIsAPositiveInteger) {
  const StatusOr<ExperimentOptions> given =
      Parse({"--scene", "s", "--out", "d", "--change-min-neighbours", "7"});
  ASSERT_TRUE(given.ok()) << given.status().message();
  EXPECT_EQ(given->change_min_neighbours, 7);
  EXPECT_FALSE(Parse({"--scene", "s", "--out", "d"})->change_min_neighbours.has_value());
  for (const char* bad : {"0", "-3", "2.5", "many"}) {
    const StatusOr<ExperimentOptions> refused =
        Parse({"--scene", "s", "--out", "d", "--change-min-neighbours", bad});
    EXPECT_EQ(refused.status().code(), StatusCode::kInvalidArgument) << bad;
  }
}

TEST(ExperimentOptions, TheResolutionIsWidthByHeightOrTheScenes) {
  const StatusOr<ExperimentOptions> given =
      Parse({"--scene", "s", "--out", "d", "--resolution", "640x480"});
  ASSERT_TRUE(given.ok()) << given.status().message();
  ASSERT_TRUE(given->resolution.has_value());
  EXPECT_EQ(given->resolution->width, 640u);
  EXPECT_EQ(given->resolution->height, 480u);
  EXPECT_FALSE(Parse({"--scene", "s", "--out", "d"})->resolution.has_value());
  for (const char* bad : {"640", "640x0", "x480", "640x480x3", "5000x480"}) {
    const StatusOr<ExperimentOptions> refused =
        Parse({"--scene", "s", "--out", "d", "--resolution", bad});
    EXPECT_EQ(refused.status().code(), StatusCode::kInvalidArgument) << bad;
    EXPECT_NE(refused.status().message().find("--resolution"), std::string::npos) << bad;
  }
}

}  // namespace
}  // namespace relmap::sim
