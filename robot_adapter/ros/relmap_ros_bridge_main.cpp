// relmap_ros_bridge: a relmap session as a ROS 1 node (docs/ros.md).
#include <ros/ros.h>

#include "ros_bridge_node.h"
#include "ros_params.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "relmap_ros_bridge");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  relmap::StatusOr<relmap::ros_bridge::NodeSettings> settings =
      relmap::ros_bridge::ReadNodeSettings(private_node);
  if (!settings.ok()) {
    ROS_FATAL("relmap_ros_bridge: %s", settings.status().message().c_str());
    return 2;
  }
  relmap::ros_bridge::RosBridgeNode bridge(node, private_node, std::move(*settings));
  relmap::Status started = bridge.Start();
  if (!started.ok()) {
    ROS_FATAL("relmap_ros_bridge: %s", started.message().c_str());
    return 1;
  }
  // Two threads: ~post_outcome and after-push clouds are answered while the timer and
  // the subscriptions go on; the maps are computed on the node's own worker.
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
