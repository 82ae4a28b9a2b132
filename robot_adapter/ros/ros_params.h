// relmap_ros_bridge's parameters, read from the parameter server (the node's private
// namespace) and validated: a parameter of the wrong type, or a value ValidateBridgeConfig
// refuses, is an error naming it. docs/ros.md lists them.
#pragma once

#include <ros/node_handle.h>

#include <string>

#include "bridge_config.h"
#include "common/status.h"

namespace relmap::ros_bridge {

struct NodeSettings {
  BridgeConfig bridge;
  // Topics and the push service, resolved in the node's namespace (remap them as usual).
  std::string cloud_topic = "cloud";
  std::string after_cloud_topic = "after_cloud";
  std::string push_service = "push";
  // How long to wait for tf2 to know the cloud's frame at its stamp.
  double tf_timeout_seconds = 0.5;
  double diagnostics_period_seconds = 1.0;
  // At most one cloud per this period is mapped (0: as fast as the server answers).
  double min_period_seconds = 0;
  // Every cloud mapped and every outcome learned is written to this bag; empty: none.
  std::string record_bag;
};

StatusOr<NodeSettings> ReadNodeSettings(const ros::NodeHandle& private_node);

}  // namespace relmap::ros_bridge
