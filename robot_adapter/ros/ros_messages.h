// ROS 1 messages to and from the bridge's plain structs (cloud_message.h): the only
// place that knows both. C++17 (ROS 1's generated headers).
#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/Marker.h>

#include "cloud_message.h"

namespace relmap::ros_bridge {

CloudMessage FromRos(const sensor_msgs::PointCloud2& cloud);
sensor_msgs::PointCloud2 ToRos(const CloudMessage& cloud);

RigidTransform FromRos(const geometry_msgs::TransformStamped& transform);

Stamp FromRos(const ros::Time& time);
ros::Time ToRos(Stamp stamp);

geometry_msgs::PoseStamped PoseOf(const TargetPose& target);
// An arrow along the target's normal, starting at its centroid; its id is the target
// supervoxel's, namespace "relmap_target".
visualization_msgs::Marker MarkerOf(const TargetPose& target);

}  // namespace relmap::ros_bridge
