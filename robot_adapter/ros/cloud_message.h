// The ROS messages the bridge speaks, as plain structs: sensor_msgs/PointCloud2 (the
// same in ROS 1 and ROS 2), a rigid transform and a target pose. The conversions and
// the exploration logic work on these, so that they build without ROS and a ROS 2 node
// only has to copy its messages into them. C++17, because ROS 1's generated message
// headers do not compile as C++20 and the node includes both.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace relmap::ros_bridge {

// sensor_msgs/PointField's datatypes.
enum class FieldType : std::uint8_t {
  kInt8 = 1,
  kUint8 = 2,
  kInt16 = 3,
  kUint16 = 4,
  kInt32 = 5,
  kUint32 = 6,
  kFloat32 = 7,
  kFloat64 = 8,
};

struct PointField {
  std::string name;
  std::uint32_t offset = 0;
  FieldType datatype = FieldType::kFloat32;
  std::uint32_t count = 1;
};

// A ROS time: seconds and nanoseconds since the epoch.
struct Stamp {
  std::uint32_t sec = 0;
  std::uint32_t nsec = 0;
  bool operator==(const Stamp& other) const { return sec == other.sec && nsec == other.nsec; }
};

// sensor_msgs/PointCloud2 with its header's frame and stamp.
struct CloudMessage {
  std::string frame_id;
  Stamp stamp;
  std::uint32_t height = 1;
  std::uint32_t width = 0;
  std::vector<PointField> fields;
  bool is_bigendian = false;
  std::uint32_t point_step = 0;
  std::uint32_t row_step = 0;
  std::vector<std::uint8_t> data;
  bool is_dense = false;
};

struct Vector3d {
  double x = 0, y = 0, z = 0;
};

// Unit quaternion.
struct Quaternion {
  double x = 0, y = 0, z = 0, w = 1;
};

// A rigid transform taking points from a source frame into `target_frame`
// (geometry_msgs/Transform): p' = rotation · p + translation.
struct RigidTransform {
  std::string target_frame;
  Quaternion rotation;
  Vector3d translation;
};

// The push target as geometry_msgs/PoseStamped: the supervoxel's centroid, oriented so
// that its x axis is the supervoxel's normal (an RViz arrow along x shows the normal).
struct TargetPose {
  std::string frame_id;
  Stamp stamp;
  Vector3d position;
  Quaternion orientation;
  Vector3d normal;
  std::uint32_t supervoxel_id = 0;
};

}  // namespace relmap::ros_bridge
