// What the ROS tests share: a rosmaster on a loopback port for the test binary, child
// processes (the bridge, the replay tool), the real Kinect frames as PointCloud2, and
// waiting for messages. C++17, as every ROS 1 translation unit.
#pragma once

#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <sys/types.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace relmap::ros_testing {

// A child process with its output in `log_path`; stopped by SIGINT (as roslaunch stops
// nodes), SIGKILL after 10 s.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& argv, const std::string& log_path);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool Running();
  // How it ended, once Running() or Stop() has seen it end.
  int wait_status() const { return wait_status_; }
  // The wait status, or -1 when it had already been reaped.
  int Stop();
  const std::string& log_path() const { return log_path_; }

 private:
  pid_t pid_ = -1;
  int wait_status_ = -1;
  std::string log_path_;
};

// rosmaster on a free loopback port, ROS_MASTER_URI and ROS_HOME (a temporary
// directory) set for this process and its children, and ros::init done: once per test
// binary. Empty when it worked, else why not.
std::string StartRosOnce();

// The Kinect frame `name` of the project's real data as a PointCloud2 in frame
// "kinect" stamped `stamp`; nullopt when the data is not there.
std::optional<sensor_msgs::PointCloud2> KinectCloud(const std::string& name, ros::Time stamp);

// Every message of a topic since construction.
template <typename Message>
class Inbox {
 public:
  Inbox(ros::NodeHandle& node, const std::string& topic)
      : subscriber_(node.subscribe(topic, 10, &Inbox::Receive, this)) {}

  // The first message (since construction) for which `accept` holds, waiting up to
  // `seconds` for it.
  std::optional<Message> WaitFor(const std::function<bool(const Message&)>& accept,
                                 double seconds = 30) {
    std::unique_lock lock(mutex_);
    std::optional<Message> found;
    arrived_.wait_for(lock, std::chrono::duration<double>(seconds), [&] {
      for (const Message& message : messages_) {
        if (accept(message)) {
          found = message;
          return true;
        }
      }
      return false;
    });
    return found;
  }
  // Waits until a publisher of the topic is connected to this inbox.
  bool Connected(double seconds = 20) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (subscriber_.getNumPublishers() == 0) {
      if (std::chrono::steady_clock::now() > until) return false;
      ros::WallDuration(0.02).sleep();
    }
    return true;
  }
  std::size_t size() {
    std::lock_guard lock(mutex_);
    return messages_.size();
  }
  const ros::Subscriber& subscriber() const { return subscriber_; }

 private:
  void Receive(const boost::shared_ptr<const Message>& message) {
    {
      std::lock_guard lock(mutex_);
      messages_.push_back(*message);
    }
    arrived_.notify_all();
  }

  ros::Subscriber subscriber_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<Message> messages_;
};

// Waits until `publisher` has `subscribers` subscribers (the bridge is connected).
bool WaitForSubscribers(const ros::Publisher& publisher, std::uint32_t subscribers = 1,
                        double seconds = 20);

}  // namespace relmap::ros_testing
