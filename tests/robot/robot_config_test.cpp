// relmap-robot's config file: defaults, and the mistakes it refuses.
#include "robot_config.h"

#include <gtest/gtest.h>

namespace relmap::robot {
namespace {

constexpr const char* kWorkspace =
    R"("workspace": {"min_x": -0.5, "max_x": 0.5, "min_y": -0.5, "max_y": 0.5, "min_z": 0.3, "max_z": 1.5})";

std::string ExecConfig(const std::string& extra) {
  return R"({"source": {"directory": {"path": "/tmp/clouds"}},
             "driver": {"exec": {"command": ["./push.sh"]}})" +
         extra + "}";
}

TEST(RobotConfig, FillsTheDefaults) {
  StatusOr<RobotConfig> config = ParseRobotConfig(ExecConfig(std::string(", ") + kWorkspace), "t");
  ASSERT_TRUE(config.ok()) << config.status().message();
  EXPECT_EQ(config->max_pushes(), kDefaultMaxPushes);
  EXPECT_EQ(config->retries(), 2u);
  EXPECT_EQ(config->max_iterations(), 4 * kDefaultMaxPushes);
  EXPECT_EQ(config->driver().exec().timeout_seconds(), kDefaultDriverTimeoutSeconds);
}

TEST(RobotConfig, TheExecDriverNeedsAWorkspaceBox) {
  StatusOr<RobotConfig> config = ParseRobotConfig(ExecConfig(""), "robot.json");
  ASSERT_FALSE(config.ok());
  EXPECT_NE(config.status().message().find("workspace"), std::string::npos);
}

TEST(RobotConfig, RefusesUnknownFieldsAnEmptyBoxAndASimDriverWithoutTheSimulator) {
  EXPECT_FALSE(
      ParseRobotConfig(ExecConfig(std::string(", ") + kWorkspace + R"(, "max_push": 3)"), "t")
          .ok());
  EXPECT_FALSE(
      ParseRobotConfig(ExecConfig(R"(, "workspace": {"min_x": 1, "max_x": 0})"), "t").ok());
  EXPECT_FALSE(
      ParseRobotConfig(R"({"source": {"directory": {"path": "d"}}, "driver": {"sim": {}}})", "t")
          .ok());
}

TEST(InWorkspace, BoundsAreInside) {
  v1::WorkspaceBox box;
  box.set_min_x(-1);
  box.set_max_x(1);
  box.set_min_y(-1);
  box.set_max_y(1);
  box.set_min_z(0.5f);
  box.set_max_z(1);
  EXPECT_TRUE(InWorkspace(box, 1, -1, 0.5));
  EXPECT_FALSE(InWorkspace(box, 0, 0, 1.01));
}

}  // namespace
}  // namespace relmap::robot
