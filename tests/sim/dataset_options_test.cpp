// `relmap-sim dataset`'s flags: defaults, the resolution, and INVALID_ARGUMENT per misuse.
#include "dataset_options.h"

#include <gtest/gtest.h>

#include <vector>

namespace relmap::sim {
namespace {

StatusOr<DatasetOptions> Parse(std::vector<const char*> words) {
  words.insert(words.begin(), "dataset");
  return ParseDatasetOptions(static_cast<int>(words.size()), words.data(), 1);
}

TEST(DatasetOptions, DefaultsAreTwentyFramesOfSeedOneWithTheFramesBesideTheCsv) {
  const StatusOr<DatasetOptions> options = Parse({"--scene", "MoveableBalls", "--out", "x.csv"});
  ASSERT_TRUE(options.ok()) << options.status().message();
  EXPECT_EQ(options->frames, 20);
  EXPECT_EQ(options->seed, 1u);
  EXPECT_FALSE(options->resolution.has_value());
  EXPECT_EQ(options->frames_out, "x.csv.frames");
  EXPECT_TRUE(options->server.empty());
}

TEST(DatasetOptions, ReadsEveryFlag) {
  const StatusOr<DatasetOptions> options =
      Parse({"--scene", "s", "--out", "x.csv", "--frames", "5", "--seed", "9", "--resolution",
             "640x480", "--frames-out", "f.txt", "--server", "host:1"});
  ASSERT_TRUE(options.ok()) << options.status().message();
  EXPECT_EQ(options->frames, 5);
  EXPECT_EQ(options->seed, 9u);
  ASSERT_TRUE(options->resolution.has_value());
  EXPECT_EQ(options->resolution->width, 640u);
  EXPECT_EQ(options->resolution->height, 480u);
  EXPECT_EQ(options->frames_out, "f.txt");
  EXPECT_EQ(options->server, "host:1");
}

TEST(DatasetOptions, PhysicalModeTakesATruthFileBesideItsCsv) {
  const StatusOr<DatasetOptions> oracle = Parse({"--scene", "s", "--out", "x.csv"});
  ASSERT_TRUE(oracle.ok()) << oracle.status().message();
  EXPECT_EQ(oracle->mode, LabellingMode::kOracle);
  EXPECT_TRUE(oracle->truth_out.empty());
  const StatusOr<DatasetOptions> physical =
      Parse({"--scene", "s", "--out", "x.csv", "--truth-out", "t.csv", "--mode", "physical"});
  ASSERT_TRUE(physical.ok()) << physical.status().message();
  EXPECT_EQ(physical->mode, LabellingMode::kPhysical);
  EXPECT_EQ(physical->truth_out, "t.csv");
}

TEST(DatasetOptions, ATruthFileOverAnotherOutputIsRefused) {
  for (const std::vector<const char*>& words : std::vector<std::vector<const char*>>{
           {"--scene", "s", "--out", "x.csv", "--mode", "physical", "--truth-out", "x.csv"},
           {"--scene", "s", "--out", "x.csv", "--mode", "physical", "--truth-out",
            "x.csv.frames"}}) {
    const StatusOr<DatasetOptions> options = Parse(words);
    ASSERT_FALSE(options.ok()) << words.back();
    EXPECT_EQ(options.status().code(), StatusCode::kInvalidArgument);
  }
}

TEST(DatasetOptions, MisuseIsAnInvalidArgumentNamingTheFlag) {
  const std::vector<std::pair<std::vector<const char*>, std::string>> cases = {
      {{"--out", "x.csv"}, "--scene"},
      {{"--scene", "s"}, "--out"},
      {{"--scene", "s", "--out", "x.csv", "--frames", "0"}, "--frames"},
      {{"--scene", "s", "--out", "x.csv", "--resolution", "640"}, "--resolution"},
      {{"--scene", "s", "--out", "x.csv", "--resolution", "640x0"}, "--resolution"},
      {{"--scene", "s", "--out", "x.csv", "--frames-out", "x.csv"}, "--frames-out"},
      {{"--scene", "s", "--out", "x.csv", "--server", "a:1", "--server-binary", "b"}, "--server"},
      {{"--scene", "s", "--out", "x.csv", "--mode", "pushed"}, "--mode"},
      {{"--scene", "s", "--out", "x.csv", "--truth-out", "t.csv"}, "--truth-out"}};
  for (const auto& [words, flag] : cases) {
    const StatusOr<DatasetOptions> options = Parse(words);
    ASSERT_FALSE(options.ok()) << flag;
    EXPECT_EQ(options.status().code(), StatusCode::kInvalidArgument) << flag;
    EXPECT_NE(options.status().message().find(flag), std::string::npos)
        << options.status().message();
  }
}

}  // namespace
}  // namespace relmap::sim
