// relmap_ros_replay: a recorded bag of clouds and outcomes into a new relmap session,
// in the bag's order, so that a real-robot run can be shared and re-run (docs/ros.md).
// Each cloud is mapped, each outcome posted for the frame of the cloud it names by
// stamp: the session learns the same samples as the recorded one.
#include <relmap_ros/Outcome.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud2.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "bridge.h"
#include "common/command_line.h"
#include "ros_messages.h"

namespace {

constexpr const char* kProgram = "relmap_ros_replay";
constexpr const char* kUsage =
    "usage: relmap_ros_replay BAG --server HOST:PORT [--seed N] [--admin-key KEY]\n"
    "                         [--clouds TOPIC] [--outcomes TOPIC]\n"
    "Maps every sensor_msgs/PointCloud2 of the bag (of TOPIC, when several topics have "
    "clouds) and\nposts every relmap_ros/Outcome in a new session; prints its id and "
    "token.";

struct Arguments {
  std::string bag;
  std::string clouds;
  std::string outcomes;
  relmap::ros_bridge::BridgeConfig config;
};

Arguments Parse(int argc, char** argv) {
  Arguments arguments;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) relmap::tools::ExitWithError(kProgram, flag + " needs a value");
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h") {
      std::puts(kUsage);
      std::exit(0);
    } else if (flag == "--server") {
      arguments.config.client.address = value();
    } else if (flag == "--seed") {
      const std::string seed = value();
      arguments.config.session.set_seed(static_cast<std::uint64_t>(
          relmap::tools::ParseNumberOrExit(kProgram, flag, seed.c_str())));
    } else if (flag == "--admin-key") {
      arguments.config.admin_key = value();
    } else if (flag == "--clouds") {
      arguments.clouds = value();
    } else if (flag == "--outcomes") {
      arguments.outcomes = value();
    } else if (!flag.empty() && flag[0] != '-' && arguments.bag.empty()) {
      arguments.bag = flag;
    } else {
      relmap::tools::ExitWithError(kProgram, "unexpected argument " + flag + "\n" + kUsage);
    }
  }
  if (arguments.bag.empty()) relmap::tools::ExitWithError(kProgram, kUsage);
  const relmap::Status valid = relmap::ros_bridge::ValidateBridgeConfig(arguments.config);
  if (!valid.ok()) relmap::tools::ExitWithError(kProgram, valid.message());
  return arguments;
}

// Whether `message` is one of the bag's clouds (or outcomes) this replay takes.
bool Takes(const rosbag::MessageInstance& message, const char* datatype, const std::string& topic) {
  return message.getDataType() == datatype && (topic.empty() || message.getTopic() == topic);
}

int Replay(const Arguments& arguments) {
  rosbag::Bag bag(arguments.bag, rosbag::bagmode::Read);
  relmap::ros_bridge::Bridge bridge(arguments.config);
  if (relmap::Status started = bridge.Start(); !started.ok()) {
    relmap::tools::ExitWithError(kProgram, started.message());
  }
  int frames = 0, outcomes = 0;
  std::string cloud_topic = arguments.clouds;
  for (const rosbag::MessageInstance& message : rosbag::View(bag)) {
    if (Takes(message, "sensor_msgs/PointCloud2", cloud_topic)) {
      if (cloud_topic.empty()) cloud_topic = message.getTopic();
      const auto cloud = message.instantiate<sensor_msgs::PointCloud2>();
      relmap::StatusOr<relmap::ros_bridge::FrameMaps> maps =
          bridge.Map(relmap::ros_bridge::FromRos(*cloud), std::nullopt);
      if (!maps.ok()) relmap::tools::ExitWithError(kProgram, maps.status().message());
      ++frames;
    } else if (Takes(message, "relmap_ros/Outcome", arguments.outcomes)) {
      const auto outcome = message.instantiate<relmap_ros::Outcome>();
      relmap::StatusOr<relmap::ros_bridge::OutcomeAnswer> posted =
          bridge.PostLabel(relmap::ros_bridge::FromRos(outcome->header.stamp),
                           outcome->supervoxel_id, outcome->moved);
      if (!posted.ok()) relmap::tools::ExitWithError(kProgram, posted.status().message());
      ++outcomes;
    }
  }
  std::printf("session_id %s\nsession_token %s\n", bridge.session_id().c_str(),
              bridge.session_token().c_str());
  std::fprintf(stderr, "%s: %d frames of %s, %d outcomes replayed into session %s\n", kProgram,
               frames, cloud_topic.c_str(), outcomes, bridge.session_id().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Arguments arguments = Parse(argc, argv);
  return relmap::tools::ExitCodeOf(kProgram, [&] { return Replay(arguments); });
}
