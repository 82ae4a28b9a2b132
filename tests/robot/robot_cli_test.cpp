// The relmap-robot executable: a run with the simulator as the robot, then its replay.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "integration/test_support.h"
#include "local_server.h"

namespace relmap::robot {
namespace {

TEST(RelmapRobot, RunsWithTheSimulatorAndReplaysTheRecordedRun) {
  StatusOr<std::unique_ptr<client::LocalServer>> server =
      client::LocalServer::Start(RELMAP_SERVER_BINARY, {true, {}, ""});
  ASSERT_TRUE(server.ok()) << server.status().message();
  relmap::testing::TemporaryDirectory directory;
  const std::string config = directory.path() + "/robot.json";
  std::ofstream(config) << R"({"source": {"sim": {"scene": "MoveableBalls", "seed": 2,
                                                  "width": 160, "height": 120}},
      "driver": {"sim": {}},
      "session": {"seed": 4, "change_detector": {"ror_min_neighbours": 3}},
      "max_pushes": 3, "run_dir": ")"
                        << directory.path() << R"(/run"})";
  const std::string robot = std::string(RELMAP_ROBOT_BINARY) + " ";
  const std::string server_flag = " --server " + (*server)->address();
  ASSERT_EQ(std::system((robot + "run --config " + config + server_flag + " 2> " +
                         directory.path() + "/run.log")
                            .c_str()),
            0)
      << relmap::testing::ReadFile(directory.path() + "/run.log");
  const std::string curve = directory.path() + "/curve.csv";
  ASSERT_EQ(std::system((robot + "replay " + directory.path() + "/run" + server_flag + " > " +
                         curve + " 2> /dev/null")
                            .c_str()),
            0);
  std::ifstream in(curve);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "iteration,supervoxel,label,accuracy");
  int rows = 0;
  for (std::string row; std::getline(in, row); ++rows) {
    EXPECT_NE(row.back(), ',') << "every row has an accuracy: " << row;
  }
  EXPECT_GE(rows, 1);
  EXPECT_LE(rows, 3);
}

TEST(RelmapRobot, ABadConfigIsRefusedWithItsReason) {
  relmap::testing::TemporaryDirectory directory;
  const std::string config = directory.path() + "/robot.json";
  std::ofstream(config) << R"({"source": {"directory": {"path": "clouds"}},
      "driver": {"exec": {"command": ["./push.sh"]}}})";
  const std::string log = directory.path() + "/run.log";
  const int status = std::system(
      (std::string(RELMAP_ROBOT_BINARY) + " run --config " + config + " 2> " + log).c_str());
  EXPECT_NE(status, 0);
  EXPECT_NE(relmap::testing::ReadFile(log).find("workspace"), std::string::npos);
}

}  // namespace
}  // namespace relmap::robot
