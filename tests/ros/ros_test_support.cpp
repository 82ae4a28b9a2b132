#include "ros_test_support.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <thread>

#include "cloud_conversion.h"
#include "common/pcd/pcd_reader.h"
#include "ros_messages.h"

namespace relmap::ros_testing {
namespace {

// A port the kernel has just found free on loopback.
int FreePort() {
  const int socket_fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  int port = 0;
  if (::bind(socket_fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      ::getsockname(socket_fd, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    port = ntohs(address.sin_port);
  }
  ::close(socket_fd);
  return port;
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::string& log_path)
    : log_path_(log_path) {
  std::vector<char*> arguments;
  for (const std::string& argument : argv) arguments.push_back(const_cast<char*>(argument.c_str()));
  arguments.push_back(nullptr);
  pid_ = ::fork();
  if (pid_ == 0) {
    const int log = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    ::setpgid(0, 0);
    ::execvp(arguments[0], arguments.data());
    ::_exit(127);
  }
}

ChildProcess::~ChildProcess() { Stop(); }

bool ChildProcess::Running() {
  if (pid_ <= 0) return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) == pid_) {
    pid_ = -1;
    wait_status_ = status;
    return false;
  }
  return true;
}

int ChildProcess::Stop() {
  if (pid_ <= 0) return -1;
  ::kill(pid_, SIGINT);
  int status = 0;
  for (int waited = 0; waited < 1000; ++waited) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      wait_status_ = status;
      return status;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
  wait_status_ = status;
  return status;
}

namespace {

// The master and its ROS_HOME, for the test binary's life: a GoogleTest environment, torn
// down when the tests have run and before the process exits. Torn down by a static's
// destructor instead, it ran after the statics ros::init had made were destroyed: ASan
// found ros::ServiceManager reading this node's freed name while the spinner's node
// handle shut it down.
class RosEnvironment final : public ::testing::Environment {
 public:
  RosEnvironment() {
    char home_template[] = "/tmp/relmap-ros-test-XXXXXX";
    if (::mkdtemp(home_template) != nullptr) home_ = home_template;
  }
  void TearDown() override {
    if (spinner_) spinner_->stop();
    spinner_.reset();
    if (ros::isStarted()) ros::shutdown();
    master_.reset();
    if (!home_.empty()) std::filesystem::remove_all(home_);
    home_.clear();
  }
  RosEnvironment(const RosEnvironment&) = delete;
  RosEnvironment& operator=(const RosEnvironment&) = delete;

  // Empty when the master is up and ros::init done, else why not.
  std::string Start() {
    if (home_.empty()) return "no temporary directory";
    const int port = FreePort();
    if (port == 0) return "no free port";
    const std::string uri = "http://127.0.0.1:" + std::to_string(port);
    ::setenv("ROS_MASTER_URI", uri.c_str(), 1);
    ::setenv("ROS_HOSTNAME", "127.0.0.1", 1);
    ::setenv("ROS_HOME", home_.c_str(), 1);
    master_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{"rosmaster", "--core", "-p", std::to_string(port)},
        home_ + "/rosmaster.log");
    int argc = 0;
    ros::init(argc, nullptr, "relmap_ros_test",
              ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
    for (int tries = 0; tries < 200 && !ros::master::check(); ++tries) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!ros::master::check()) return "rosmaster did not come up on " + uri;
    ros::start();
    spinner_ = std::make_unique<ros::AsyncSpinner>(2);
    spinner_->start();
    return "";
  }

 private:
  std::string home_;
  std::unique_ptr<ChildProcess> master_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
};

}  // namespace

std::string StartRosOnce() {
  // GoogleTest owns the environment and calls its TearDown at the end of the run, also
  // for one added while the tests run.
  static const std::string failure = [] {
    auto* environment = new RosEnvironment;
    ::testing::AddGlobalTestEnvironment(environment);
    return environment->Start();
  }();
  return failure;
}

std::optional<sensor_msgs::PointCloud2> KinectCloud(const std::string& name, ros::Time stamp) {
  StatusOr<std::string> bytes =
      pcd::ReadFileBytes(std::string(RELMAP_REAL_DATA_DIR) + "/" + name, 64ULL << 20);
  if (!bytes.ok()) return std::nullopt;
  StatusOr<pcd::Points> points = pcd::ReadPcd(*bytes);
  if (!points.ok()) return std::nullopt;
  return ros_bridge::ToRos(
      ros_bridge::EncodeCloudMessage(*points, "kinect", ros_bridge::FromRos(stamp)));
}

bool WaitForSubscribers(const ros::Publisher& publisher, std::uint32_t subscribers,
                        double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (publisher.getNumSubscribers() < subscribers) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

}  // namespace relmap::ros_testing
