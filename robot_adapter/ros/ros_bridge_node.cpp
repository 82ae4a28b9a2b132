// Logs go to rosout (ROS_INFO and friends), where ROS users look: one line per event,
// each with the session id.
#include "ros_bridge_node.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <relmap_ros/Outcome.h>
#include <relmap_ros/Push.h>
#include <tf2/exceptions.h>
#include <visualization_msgs/Marker.h>

#include <chrono>
#include <sstream>

#include "ros_messages.h"

namespace relmap::ros_bridge {
namespace {

relmap_ros::Outcome OutcomeMessage(const OutcomeAnswer& outcome) {
  relmap_ros::Outcome message;
  message.header.stamp = ToRos(outcome.stamp);
  message.header.frame_id = outcome.frame;
  message.supervoxel_id = outcome.supervoxel_id;
  message.moved = outcome.moved;
  message.from_after_cloud = outcome.from_after_cloud;
  message.server_frame_id = outcome.frame_id;
  return message;
}

diagnostic_msgs::KeyValue KeyValue(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue pair;
  pair.key = key;
  pair.value = value;
  return pair;
}

}  // namespace

RosBridgeNode::RosBridgeNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node,
                             NodeSettings settings)
    : node_(node),
      private_node_(private_node),
      settings_(std::move(settings)),
      bridge_(settings_.bridge) {}

RosBridgeNode::~RosBridgeNode() {
  {
    std::lock_guard lock(slot_mutex_);
    stopping_ = true;
  }
  slot_changed_.notify_all();
  if (worker_.joinable()) worker_.join();
  std::lock_guard lock(bag_mutex_);
  if (bag_) bag_->close();
}

Status RosBridgeNode::Start() {
  Status started = bridge_.Start();
  if (!started.ok()) return started;
  ROS_INFO("relmap_ros_bridge: session %s on %s", bridge_.session_id().c_str(),
           settings_.bridge.client.address.c_str());
  if (!settings_.record_bag.empty()) {
    try {
      bag_.emplace(settings_.record_bag, rosbag::bagmode::Write);
    } catch (const rosbag::BagException& e) {
      return InvalidArgumentError("~record_bag: " + std::string(e.what()));
    }
    bag_cloud_topic_ = node_.resolveName(settings_.cloud_topic);
    bag_outcome_topic_ = private_node_.resolveName("outcomes");
  }
  if (!settings_.bridge.workspace_frame.empty()) {
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, node_);
  }
  relevance_publisher_ = private_node_.advertise<sensor_msgs::PointCloud2>("relevance", 1);
  choice_publisher_ = private_node_.advertise<sensor_msgs::PointCloud2>("choice", 1);
  target_publisher_ = private_node_.advertise<geometry_msgs::PoseStamped>("target", 1);
  marker_publisher_ = private_node_.advertise<visualization_msgs::Marker>("target_marker", 1);
  outcome_publisher_ = private_node_.advertise<relmap_ros::Outcome>("outcomes", 10);
  diagnostics_publisher_ = node_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
  outcome_service_ =
      private_node_.advertiseService("post_outcome", &RosBridgeNode::OnPostOutcome, this);
  if (settings_.bridge.push_loop) {
    push_client_ = node_.serviceClient<relmap_ros::Push>(settings_.push_service);
  }
  worker_ = std::thread([this] { Work(); });
  // Queues of one: a cloud is megabytes, and only the latest one matters.
  cloud_subscriber_ = node_.subscribe(settings_.cloud_topic, 1, &RosBridgeNode::OnCloud, this);
  after_cloud_subscriber_ =
      node_.subscribe(settings_.after_cloud_topic, 1, &RosBridgeNode::OnAfterCloud, this);
  diagnostics_timer_ =
      node_.createWallTimer(ros::WallDuration(settings_.diagnostics_period_seconds),
                            &RosBridgeNode::PublishDiagnostics, this);
  return OkStatus();
}

void RosBridgeNode::OnCloud(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  ++clouds_;
  {
    std::lock_guard lock(slot_mutex_);
    if (waiting_) ++dropped_;
    waiting_ = cloud;
  }
  slot_changed_.notify_one();
}

void RosBridgeNode::Work() {
  auto next_allowed = std::chrono::steady_clock::now();
  for (;;) {
    sensor_msgs::PointCloud2ConstPtr cloud;
    {
      std::unique_lock lock(slot_mutex_);
      slot_changed_.wait(lock, [this] { return stopping_ || waiting_ != nullptr; });
      if (stopping_) return;
      cloud = std::move(waiting_);
      waiting_.reset();
    }
    std::this_thread::sleep_until(next_allowed);
    next_allowed = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double>(settings_.min_period_seconds));
    Process(*cloud);
  }
}

StatusOr<std::optional<RigidTransform>> RosBridgeNode::ToWorkspace(const std_msgs::Header& header) {
  if (settings_.bridge.workspace_frame.empty()) return std::optional<RigidTransform>();
  try {
    const geometry_msgs::TransformStamped transform =
        tf_buffer_->lookupTransform(settings_.bridge.workspace_frame, header.frame_id, header.stamp,
                                    ros::Duration(settings_.tf_timeout_seconds));
    return std::optional<RigidTransform>(FromRos(transform));
  } catch (const tf2::TransformException& e) {
    return FailedPreconditionError("no transform from " + header.frame_id + " to " +
                                   settings_.bridge.workspace_frame + ": " + e.what());
  }
}

void RosBridgeNode::Process(const sensor_msgs::PointCloud2& cloud) {
  StatusOr<std::optional<RigidTransform>> transform = ToWorkspace(cloud.header);
  if (!transform.ok()) return NoteError("cloud", transform.status());
  CloudStep step = bridge_.OnCloud(FromRos(cloud), *transform);
  if (step.after_outcome) {
    if (step.after_outcome->ok()) {
      Announce(**step.after_outcome);
    } else {
      NoteError("after-push cloud", step.after_outcome->status());
    }
  }
  if (!step.maps.ok()) return NoteError("cloud", step.maps.status());
  const FrameMaps& maps = *step.maps;
  ++mapped_;
  last_server_ms_ = maps.server_ms;
  if (maps.sent) Record(bag_cloud_topic_, ToRos(*maps.sent));
  Publish(maps);
  ROS_INFO(
      "relmap_ros_bridge: session %s frame %lu: %zu supervoxels, target %s, %.0f ms",
      bridge_.session_id().c_str(), static_cast<unsigned long>(maps.frame_id), maps.supervoxels,
      maps.target ? std::to_string(maps.target->supervoxel_id).c_str() : "none", maps.server_ms);
  if (bridge_.TakePush(maps)) Push(maps);
}

void RosBridgeNode::Publish(const FrameMaps& maps) {
  relevance_publisher_.publish(ToRos(maps.relevance));
  choice_publisher_.publish(ToRos(maps.choice));
  if (maps.target) {
    target_publisher_.publish(PoseOf(*maps.target));
    marker_publisher_.publish(MarkerOf(*maps.target));
  }
}

void RosBridgeNode::Push(const FrameMaps& maps) {
  relmap_ros::Push push;
  push.request.target = PoseOf(*maps.target);
  push.request.supervoxel_id = maps.target->supervoxel_id;
  push.request.push = static_cast<std::uint32_t>(bridge_.pushes());
  if (!push_client_.call(push)) {
    return NoteError(
        "push", Status(StatusCode::kUnavailable, "the push service " + push_client_.getService() +
                                                     " did not answer; nothing learned"));
  }
  StatusOr<std::optional<OutcomeAnswer>> outcome =
      bridge_.OnPushReply(maps, {push.response.result, push.response.label, push.response.message});
  if (!outcome.ok()) return NoteError("push", outcome.status());
  ROS_INFO("relmap_ros_bridge: session %s push %u of supervoxel %u: %s %s (%s)",
           bridge_.session_id().c_str(), push.request.push, push.request.supervoxel_id,
           push.response.result.c_str(), push.response.label.c_str(),
           push.response.message.c_str());
  if (*outcome) Announce(**outcome);
}

void RosBridgeNode::OnAfterCloud(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  StatusOr<std::optional<RigidTransform>> transform = ToWorkspace(cloud->header);
  if (!transform.ok()) return NoteError("after-push cloud", transform.status());
  StatusOr<OutcomeAnswer> outcome = bridge_.PostAfterCloud(FromRos(*cloud), *transform);
  if (!outcome.ok()) return NoteError("after-push cloud", outcome.status());
  Announce(*outcome);
}

bool RosBridgeNode::OnPostOutcome(relmap_ros::PostOutcome::Request& request,
                                  relmap_ros::PostOutcome::Response& response) {
  StatusOr<OutcomeAnswer> outcome =
      bridge_.PostLabel(FromRos(request.stamp), request.supervoxel_id, request.moved);
  if (!outcome.ok()) {
    NoteError("post_outcome", outcome.status());
    response.success = false;
    response.message = outcome.status().message();
    return true;
  }
  Announce(*outcome);
  response.success = true;
  response.message = "learned: supervoxel " + std::to_string(outcome->supervoxel_id) + " " +
                     (outcome->moved ? "moved" : "stayed");
  response.moveable_samples = outcome->moveable_samples;
  response.non_moveable_samples = outcome->non_moveable_samples;
  return true;
}

void RosBridgeNode::Announce(const OutcomeAnswer& outcome) {
  ++outcomes_;
  const relmap_ros::Outcome message = OutcomeMessage(outcome);
  outcome_publisher_.publish(message);
  Record(bag_outcome_topic_, message);
  ROS_INFO(
      "relmap_ros_bridge: session %s frame %lu supervoxel %u %s%s; samples %lu moveable, "
      "%lu not",
      bridge_.session_id().c_str(), static_cast<unsigned long>(outcome.frame_id),
      outcome.supervoxel_id, outcome.moved ? "moved" : "stayed",
      outcome.from_after_cloud ? " (change detector)" : "",
      static_cast<unsigned long>(outcome.moveable_samples),
      static_cast<unsigned long>(outcome.non_moveable_samples));
}

template <typename Message>
void RosBridgeNode::Record(const std::string& topic, const Message& message) {
  std::lock_guard lock(bag_mutex_);
  if (!bag_) return;
  try {
    bag_->write(topic, ros::Time::now(), message);
  } catch (const rosbag::BagException& e) {
    ROS_ERROR("relmap_ros_bridge: session %s: writing the bag: %s", bridge_.session_id().c_str(),
              e.what());
  }
}

void RosBridgeNode::NoteError(const std::string& what, const Status& status) {
  ++errors_;
  {
    std::lock_guard lock(error_mutex_);
    last_error_ = what + ": " + status.message();
  }
  ROS_ERROR("relmap_ros_bridge: session %s: %s: %s", bridge_.session_id().c_str(), what.c_str(),
            status.message().c_str());
}

void RosBridgeNode::PublishDiagnostics(const ros::WallTimerEvent& /*event*/) {
  diagnostic_msgs::DiagnosticStatus status;
  status.name = ros::this_node::getName() + ": relmap";
  status.hardware_id = settings_.bridge.client.address;
  {
    std::lock_guard lock(error_mutex_);
    status.level = last_error_.empty() ? diagnostic_msgs::DiagnosticStatus::OK
                                       : diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = last_error_.empty() ? "mapping" : "last error: " + last_error_;
  }
  status.values = {KeyValue("session", bridge_.session_id()),
                   KeyValue("clouds received", std::to_string(clouds_.load())),
                   KeyValue("clouds dropped (latest wins)", std::to_string(dropped_.load())),
                   KeyValue("frames mapped", std::to_string(mapped_.load())),
                   KeyValue("outcomes learned", std::to_string(outcomes_.load())),
                   KeyValue("pushes", std::to_string(bridge_.pushes())),
                   KeyValue("errors", std::to_string(errors_.load())),
                   KeyValue("last server ms", std::to_string(last_server_ms_.load()))};
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = ros::Time::now();
  array.status.push_back(status);
  diagnostics_publisher_.publish(array);
}

}  // namespace relmap::ros_bridge
