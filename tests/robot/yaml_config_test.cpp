// YAML configs: the same schema and checks as JSON, through the same parser.
#include <gtest/gtest.h>

#include <fstream>

#include "integration/test_support.h"
#include "openni2_source.h"
#include "robot_config.h"
#include "yaml_json.h"

namespace relmap::robot {
namespace {

constexpr const char* kYaml = R"(# a robot at the lab
source:
  tcp: {listen: "0.0.0.0:5000", wait_timeout_seconds: 30}
driver:
  tcp_json:
    address: arm-controller:7000
    timeout_seconds: 20
workspace: {min_x: -0.6, max_x: 0.6, min_y: -0.5, max_y: 0.5, min_z: 0.4, max_z: 2.0}
session:
  seed: 7
max_pushes: 5
dry_run: false
run_dir: run
)";

constexpr const char* kJson = R"({"source": {"tcp": {"listen": "0.0.0.0:5000",
  "wait_timeout_seconds": 30}}, "driver": {"tcp_json": {"address": "arm-controller:7000",
  "timeout_seconds": 20}}, "workspace": {"min_x": -0.6, "max_x": 0.6, "min_y": -0.5,
  "max_y": 0.5, "min_z": 0.4, "max_z": 2.0}, "session": {"seed": 7}, "max_pushes": 5,
  "dry_run": false, "run_dir": "run"})";

TEST(YamlConfig, ReadsAsTheSameConfigAsItsJson) {
  StatusOr<RobotConfig> from_yaml = ParseRobotConfigYaml(kYaml, "robot.yaml");
  ASSERT_TRUE(from_yaml.ok()) << from_yaml.status().message();
  StatusOr<RobotConfig> from_json = ParseRobotConfig(kJson, "robot.json");
  ASSERT_TRUE(from_json.ok()) << from_json.status().message();
  EXPECT_EQ(from_yaml->SerializeAsString(), from_json->SerializeAsString());
  EXPECT_EQ(from_yaml->driver().tcp_json().connect_timeout_seconds(),
            kDefaultConnectTimeoutSeconds);
}

TEST(YamlConfig, AFileIsReadAsYamlByItsExtension) {
  relmap::testing::TemporaryDirectory directory;
  for (const char* name : {"/robot.yaml", "/robot.yml"}) {
    std::ofstream(directory.path() + name) << kYaml;
    StatusOr<RobotConfig> config = ReadRobotConfig(directory.path() + name);
    ASSERT_TRUE(config.ok()) << config.status().message();
    EXPECT_EQ(config->max_pushes(), 5u);
  }
}

TEST(YamlConfig, UnknownFieldsAreErrorsAsInJson) {
  StatusOr<RobotConfig> config =
      ParseRobotConfigYaml(std::string(kYaml) + "max_push: 3\n", "robot.yaml");
  ASSERT_FALSE(config.ok());
  EXPECT_NE(config.status().message().find("max_push"), std::string::npos)
      << config.status().message();
}

TEST(YamlToJson, PlainScalarsAreNumbersBooleansOrNullAndQuotedOnesStrings) {
  StatusOr<std::string> json =
      YamlToJson("a: 1.5e3\nb: true\nc: ~\nd: \"2\"\ne: .5\nf: [x, 'y z']\n", "t");
  ASSERT_TRUE(json.ok()) << json.status().message();
  EXPECT_EQ(*json, R"({"a":1.5e3,"b":true,"c":null,"d":"2","e":".5","f":["x","y z"]})");
}

TEST(YamlToJson, RefusesMalformedYamlDuplicateKeysAndSeveralDocuments) {
  StatusOr<std::string> malformed = YamlToJson("source:\n  tcp: {listen: [\n", "robot.yaml");
  ASSERT_FALSE(malformed.ok());
  EXPECT_NE(malformed.status().message().find("robot.yaml:"), std::string::npos);
  StatusOr<std::string> twice = YamlToJson("a: 1\nb: 2\na: 3\n", "robot.yaml");
  ASSERT_FALSE(twice.ok());
  EXPECT_NE(twice.status().message().find("robot.yaml:3"), std::string::npos)
      << twice.status().message();
  EXPECT_FALSE(YamlToJson("a: 1\n---\nb: 2\n", "t").ok());
  EXPECT_FALSE(YamlToJson("", "t").ok());
}

TEST(RobotConfigSources, TheOpenNI2SourceIsRefusedWhereTheBuildHasNone) {
  StatusOr<RobotConfig> config = ParseRobotConfigYaml(
      "source: {openni2: {}}\ndriver: {exec: {command: [./push.sh]}}\n"
      "workspace: {min_x: -1, max_x: 1, min_y: -1, max_y: 1, min_z: 0, max_z: 2}\n",
      "t");
  if (OpenNI2Available()) {
    ASSERT_TRUE(config.ok()) << config.status().message();
    EXPECT_EQ(config->source().openni2().frame_timeout_seconds(), kDefaultFrameTimeoutSeconds);
  } else {
    ASSERT_FALSE(config.ok());
    EXPECT_NE(config.status().message().find("no OpenNI2"), std::string::npos);
  }
}

TEST(RobotConfigSources, TheTcpJsonDriverNeedsAnAddressAndAWorkspace) {
  EXPECT_FALSE(
      ParseRobotConfigYaml("source: {stdin: {}}\ndriver: {tcp_json: {address: 'a:1'}}\n", "t")
          .ok());
  EXPECT_FALSE(ParseRobotConfigYaml(
                   "source: {stdin: {}}\ndriver: {tcp_json: {}}\n"
                   "workspace: {min_x: -1, max_x: 1, min_y: -1, max_y: 1, min_z: 0, max_z: 2}\n",
                   "t")
                   .ok());
}

}  // namespace
}  // namespace relmap::robot
