#include "ros_messages.h"

namespace relmap::ros_bridge {

CloudMessage FromRos(const sensor_msgs::PointCloud2& cloud) {
  CloudMessage plain;
  plain.frame_id = cloud.header.frame_id;
  plain.stamp = FromRos(cloud.header.stamp);
  plain.height = cloud.height;
  plain.width = cloud.width;
  for (const sensor_msgs::PointField& field : cloud.fields) {
    plain.fields.push_back(
        {field.name, field.offset, static_cast<FieldType>(field.datatype), field.count});
  }
  plain.is_bigendian = cloud.is_bigendian;
  plain.point_step = cloud.point_step;
  plain.row_step = cloud.row_step;
  plain.data = cloud.data;
  plain.is_dense = cloud.is_dense;
  return plain;
}

sensor_msgs::PointCloud2 ToRos(const CloudMessage& cloud) {
  sensor_msgs::PointCloud2 message;
  message.header.frame_id = cloud.frame_id;
  message.header.stamp = ToRos(cloud.stamp);
  message.height = cloud.height;
  message.width = cloud.width;
  for (const PointField& field : cloud.fields) {
    sensor_msgs::PointField out;
    out.name = field.name;
    out.offset = field.offset;
    out.datatype = static_cast<std::uint8_t>(field.datatype);
    out.count = field.count;
    message.fields.push_back(out);
  }
  message.is_bigendian = cloud.is_bigendian;
  message.point_step = cloud.point_step;
  message.row_step = cloud.row_step;
  message.data = cloud.data;
  message.is_dense = cloud.is_dense;
  return message;
}

RigidTransform FromRos(const geometry_msgs::TransformStamped& transform) {
  const geometry_msgs::Quaternion& q = transform.transform.rotation;
  const geometry_msgs::Vector3& t = transform.transform.translation;
  return {transform.header.frame_id, {q.x, q.y, q.z, q.w}, {t.x, t.y, t.z}};
}

Stamp FromRos(const ros::Time& time) { return {time.sec, time.nsec}; }

ros::Time ToRos(Stamp stamp) { return ros::Time(stamp.sec, stamp.nsec); }

geometry_msgs::PoseStamped PoseOf(const TargetPose& target) {
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = target.frame_id;
  pose.header.stamp = ToRos(target.stamp);
  pose.pose.position.x = target.position.x;
  pose.pose.position.y = target.position.y;
  pose.pose.position.z = target.position.z;
  pose.pose.orientation.x = target.orientation.x;
  pose.pose.orientation.y = target.orientation.y;
  pose.pose.orientation.z = target.orientation.z;
  pose.pose.orientation.w = target.orientation.w;
  return pose;
}

visualization_msgs::Marker MarkerOf(const TargetPose& target) {
  visualization_msgs::Marker marker;
  const geometry_msgs::PoseStamped pose = PoseOf(target);
  marker.header = pose.header;
  marker.ns = "relmap_target";
  marker.id = static_cast<std::int32_t>(target.supervoxel_id);
  marker.type = visualization_msgs::Marker::ARROW;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose = pose.pose;
  // 10 cm long, 1.5 cm thick: visible over a tabletop seen from a metre away.
  marker.scale.x = 0.10;
  marker.scale.y = 0.015;
  marker.scale.z = 0.015;
  marker.color.r = 0.0F;
  marker.color.g = 1.0F;
  marker.color.b = 0.0F;
  marker.color.a = 1.0F;
  return marker;
}

}  // namespace relmap::ros_bridge
