// The relmap-robot executable: a run with the simulator as the robot, then its replay;
// real frames on stdin with a YAML config; a clean stop on SIGTERM.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

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

TEST(RelmapRobot, TakesKinectFramesOnStdinWithAYamlConfigAndTheExampleExecDriver) {
  const std::string real = RELMAP_REAL_DATA_DIR;
  const std::string frames[2] = {real + "/kinect_static_seq_1.pcd",
                                 real + "/kinect_static_seq_2.pcd"};
  if (!std::ifstream(frames[0]) || !std::ifstream(frames[1])) GTEST_SKIP() << "no " << real;
  StatusOr<std::unique_ptr<client::LocalServer>> server =
      client::LocalServer::Start(RELMAP_SERVER_BINARY, {true, {}, ""});
  ASSERT_TRUE(server.ok()) << server.status().message();
  relmap::testing::TemporaryDirectory directory;
  const std::string config = directory.path() + "/robot.yaml";
  std::ofstream(config) << "source: {stdin: {}}\n"
                        << "driver: {exec: {command: [" << RELMAP_ROBOT_EXAMPLES
                        << "/push_driver.sh]}}\n"
                        << "workspace: {min_x: -2, max_x: 2, min_y: -2, max_y: 2, min_z: 0, "
                           "max_z: 5}\n"
                        << "max_pushes: 1\nrun_dir: " << directory.path() << "/run\n";
  const std::string log = directory.path() + "/run.log";
  ASSERT_EQ(std::system(("cat " + frames[0] + " " + frames[1] +
                         " | " RELMAP_ROBOT_BINARY " run --config " + config + " --server " +
                         (*server)->address() + " 2> " + log)
                            .c_str()),
            0)
      << relmap::testing::ReadFile(log);
  const std::string printed = relmap::testing::ReadFile(log);
  EXPECT_NE(printed.find("push_driver.sh: target {"), std::string::npos) << printed;
  // The static scene: the change detector sees no motion between the two frames.
  EXPECT_NE(printed.find("iteration 1: posted (still)"), std::string::npos) << printed;
  EXPECT_NE(relmap::testing::ReadFile(directory.path() + "/run/000001/after.pcd").size(), 0u);
}

TEST(RelmapRobot, SigtermDuringAPushLetsItFinishPostsItAndStartsNoOther) {
  const std::string frame = std::string(RELMAP_REAL_DATA_DIR) + "/kinect_static_seq_1.pcd";
  if (!std::ifstream(frame)) GTEST_SKIP() << "no " << frame;
  StatusOr<std::unique_ptr<client::LocalServer>> server =
      client::LocalServer::Start(RELMAP_SERVER_BINARY, {true, {}, ""});
  ASSERT_TRUE(server.ok()) << server.status().message();
  relmap::testing::TemporaryDirectory directory;
  const std::string pushing = directory.path() + "/pushing";
  const std::string driver = directory.path() + "/slow_arm.sh";
  std::ofstream(driver) << "#!/bin/sh\ncat > /dev/null\ntouch " << pushing
                        << "\nsleep 1\necho '{\"result\": \"done\", \"label\": \"moved\"}'\n";
  ::chmod(driver.c_str(), 0755);
  const std::string config = directory.path() + "/robot.yaml";
  std::ofstream(config) << "source: {stdin: {}}\ndriver: {exec: {command: [" << driver << "]}}\n"
                        << "workspace: {min_x: -2, max_x: 2, min_y: -2, max_y: 2, min_z: 0, "
                           "max_z: 5}\n"
                        << "max_pushes: 5\nrun_dir: " << directory.path() << "/run\n";
  const std::string log = directory.path() + "/run.log";
  // Two frames on stdin: without the stop, iteration 2 would push the second.
  const std::string frames = directory.path() + "/frames.pcd";
  ASSERT_EQ(std::system(("cat " + frame + " " + frame + " > " + frames).c_str()), 0);
  const std::string command = "exec " RELMAP_ROBOT_BINARY " run --config " + config + " --server " +
                              (*server)->address() + " < " + frames + " 2> " + log;
  const pid_t shell = ::fork();
  if (shell == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ASSERT_GT(shell, 0);
  // The shell execs relmap-robot: `shell` is its pid.
  for (int waited = 0; !std::ifstream(pushing) && waited < 300; ++waited) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(std::ifstream(pushing)) << relmap::testing::ReadFile(log);
  ::kill(shell, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(shell, &status, 0), shell);
  const std::string printed = relmap::testing::ReadFile(log);
  ASSERT_TRUE(WIFEXITED(status)) << printed;
  EXPECT_EQ(WEXITSTATUS(status), 0) << printed;
  EXPECT_NE(printed.find("iteration 1: posted (moved)"), std::string::npos) << printed;
  EXPECT_NE(printed.find("1 posted"), std::string::npos) << printed;
  EXPECT_NE(printed.find("; stopped"), std::string::npos) << printed;
  EXPECT_FALSE(std::ifstream(directory.path() + "/run/000002/status.json")) << printed;
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
