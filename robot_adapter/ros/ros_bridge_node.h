// relmap_ros_bridge's ROS 1 side: subscriptions, publications, services, tf2, the
// bag, diagnostics, and the cloud worker. Every decision is the Bridge's (bridge.h);
// this class only moves messages. Clouds are mapped on one worker thread from a slot
// of one: a cloud arriving while another is mapped replaces the one waiting (latest
// wins), and is counted as dropped.
#pragma once

#include <relmap_ros/PostOutcome.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "bridge.h"
#include "ros_params.h"

namespace relmap::ros_bridge {

class RosBridgeNode {
 public:
  RosBridgeNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node,
                NodeSettings settings);
  ~RosBridgeNode();
  RosBridgeNode(const RosBridgeNode&) = delete;
  RosBridgeNode& operator=(const RosBridgeNode&) = delete;

  // The session, the bag, then the topics and services; the worker starts.
  Status Start();

 private:
  void OnCloud(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void OnAfterCloud(const sensor_msgs::PointCloud2ConstPtr& cloud);
  bool OnPostOutcome(relmap_ros::PostOutcome::Request& request,
                     relmap_ros::PostOutcome::Response& response);
  void Work();
  void Process(const sensor_msgs::PointCloud2& cloud);
  // The transform into the workspace frame at the cloud's stamp, when one is configured.
  StatusOr<std::optional<RigidTransform>> ToWorkspace(const std_msgs::Header& header);
  void Publish(const FrameMaps& maps);
  // The push loop's call of the user's push service for `maps`' target.
  void Push(const FrameMaps& maps);
  // ~outcomes and the bag.
  void Announce(const OutcomeAnswer& outcome);
  void PublishDiagnostics(const ros::WallTimerEvent& event);
  void NoteError(const std::string& what, const Status& status);
  template <typename Message>
  void Record(const std::string& topic, const Message& message);

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  const NodeSettings settings_;
  Bridge bridge_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;

  ros::Subscriber cloud_subscriber_;
  ros::Subscriber after_cloud_subscriber_;
  ros::Publisher relevance_publisher_;
  ros::Publisher choice_publisher_;
  ros::Publisher target_publisher_;
  ros::Publisher marker_publisher_;
  ros::Publisher outcome_publisher_;
  ros::Publisher diagnostics_publisher_;
  ros::ServiceServer outcome_service_;
  ros::ServiceClient push_client_;
  ros::WallTimer diagnostics_timer_;

  std::mutex slot_mutex_;
  std::condition_variable slot_changed_;
  sensor_msgs::PointCloud2ConstPtr waiting_;  // the slot: the latest cloud not yet mapped
  bool stopping_ = false;
  std::thread worker_;

  std::mutex bag_mutex_;
  std::optional<rosbag::Bag> bag_;
  std::string bag_cloud_topic_;
  std::string bag_outcome_topic_;

  std::atomic<std::uint64_t> clouds_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<std::uint64_t> mapped_{0};
  std::atomic<std::uint64_t> outcomes_{0};
  std::atomic<std::uint64_t> errors_{0};
  std::atomic<double> last_server_ms_{0};
  std::mutex error_mutex_;
  std::string last_error_;
};

}  // namespace relmap::ros_bridge
