// Fields are read byte by byte in little-endian order (not by casting the buffer), so
// that alignment and the host's byte order cannot change what a cloud says.
#include "cloud_conversion.h"

#include <Eigen/Geometry>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace relmap::ros_bridge {
namespace {

constexpr std::size_t kPackedPointBytes = 16;  // PackedCloud: 3 float32, 4 uint8

std::size_t FieldBytes(FieldType type) {
  switch (type) {
    case FieldType::kInt8:
    case FieldType::kUint8:
      return 1;
    case FieldType::kInt16:
    case FieldType::kUint16:
      return 2;
    case FieldType::kInt32:
    case FieldType::kUint32:
    case FieldType::kFloat32:
      return 4;
    case FieldType::kFloat64:
      return 8;
  }
  return 0;
}

std::uint64_t LittleEndian(const std::uint8_t* bytes, std::size_t size) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < size; ++i) value |= std::uint64_t{bytes[i]} << (8 * i);
  return value;
}

void PutLittleEndian(std::uint32_t value, std::uint8_t* out) {
  for (int byte = 0; byte < 4; ++byte) out[byte] = static_cast<std::uint8_t>(value >> (8 * byte));
}

// A field the decoder reads, checked against the point's size.
StatusOr<const PointField*> FindField(const CloudMessage& cloud, const std::string& name) {
  for (const PointField& field : cloud.fields) {
    if (field.name != name) continue;
    if (FieldBytes(field.datatype) == 0) {
      return InvalidArgumentError("PointCloud2 field " + name + " has an unknown datatype " +
                                  std::to_string(static_cast<int>(field.datatype)));
    }
    if (field.count < 1 ||
        std::uint64_t{field.offset} + FieldBytes(field.datatype) > cloud.point_step) {
      return InvalidArgumentError("PointCloud2 field " + name + " (offset " +
                                  std::to_string(field.offset) + ") does not fit point_step " +
                                  std::to_string(cloud.point_step));
    }
    return &field;
  }
  return static_cast<const PointField*>(nullptr);
}

StatusOr<const PointField*> CoordinateField(const CloudMessage& cloud, const std::string& name) {
  StatusOr<const PointField*> field = FindField(cloud, name);
  if (!field.ok()) return field.status();
  if (*field == nullptr) return InvalidArgumentError("PointCloud2 has no field " + name);
  if ((*field)->datatype != FieldType::kFloat32 && (*field)->datatype != FieldType::kFloat64) {
    return InvalidArgumentError("PointCloud2 field " + name + " is not float32 or float64");
  }
  return field;
}

// rgb or rgba: 4 bytes holding 0xAARRGGBB, typed float32 (PCL) or uint32.
StatusOr<const PointField*> ColourField(const CloudMessage& cloud) {
  for (const char* name : {"rgb", "rgba"}) {
    StatusOr<const PointField*> field = FindField(cloud, name);
    if (!field.ok()) return field.status();
    if (*field == nullptr) continue;
    if (FieldBytes((*field)->datatype) != 4) {
      return InvalidArgumentError(std::string("PointCloud2 field ") + name +
                                  " is not 4 bytes (float32 or uint32)");
    }
    return field;
  }
  return InvalidArgumentError(
      "PointCloud2 has no rgb or rgba field: relmap's features need the colour");
}

float ReadCoordinate(const std::uint8_t* point, const PointField& field) {
  const std::uint64_t bits = LittleEndian(point + field.offset, FieldBytes(field.datatype));
  if (field.datatype == FieldType::kFloat64) {
    return static_cast<float>(std::bit_cast<double>(bits));
  }
  return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
}

}  // namespace

StatusOr<pcd::Points> DecodeCloudMessage(const CloudMessage& cloud) {
  if (cloud.is_bigendian) return InvalidArgumentError("PointCloud2 is big-endian");
  if (cloud.width == 0 || cloud.height == 0) {
    return InvalidArgumentError("PointCloud2 is empty (width " + std::to_string(cloud.width) +
                                ", height " + std::to_string(cloud.height) + ")");
  }
  if (std::uint64_t{cloud.row_step} < std::uint64_t{cloud.width} * cloud.point_step) {
    return InvalidArgumentError("PointCloud2 row_step " + std::to_string(cloud.row_step) +
                                " is below width × point_step");
  }
  if (cloud.data.size() < std::uint64_t{cloud.row_step} * cloud.height) {
    return InvalidArgumentError("PointCloud2 has " + std::to_string(cloud.data.size()) +
                                " bytes of data, not row_step × height");
  }
  const PointField* axes[3] = {};
  const char* names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    StatusOr<const PointField*> field = CoordinateField(cloud, names[axis]);
    if (!field.ok()) return field.status();
    axes[axis] = *field;
  }
  StatusOr<const PointField*> colour = ColourField(cloud);
  if (!colour.ok()) return colour.status();

  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  pcd::Points points;
  points.width = cloud.width;
  points.height = cloud.height;
  points.points.reserve(std::size_t{cloud.width} * cloud.height);
  for (std::uint32_t row = 0; row < cloud.height; ++row) {
    for (std::uint32_t column = 0; column < cloud.width; ++column) {
      const std::uint8_t* at = cloud.data.data() + std::size_t{row} * cloud.row_step +
                               std::size_t{column} * cloud.point_step;
      pcd::Point point;
      point.x = ReadCoordinate(at, *axes[0]);
      point.y = ReadCoordinate(at, *axes[1]);
      point.z = ReadCoordinate(at, *axes[2]);
      if (!(std::isfinite(point.x) && std::isfinite(point.y) && std::isfinite(point.z))) {
        point.x = point.y = point.z = kNan;
      }
      const auto argb = static_cast<std::uint32_t>(LittleEndian(at + (*colour)->offset, 4));
      point.r = static_cast<std::uint8_t>(argb >> 16);
      point.g = static_cast<std::uint8_t>(argb >> 8);
      point.b = static_cast<std::uint8_t>(argb);
      points.points.push_back(point);
    }
  }
  return points;
}

void TransformPoints(const RigidTransform& transform, pcd::Points* points) {
  const Eigen::Quaterniond rotation(transform.rotation.w, transform.rotation.x,
                                    transform.rotation.y, transform.rotation.z);
  const Eigen::Vector3d translation(transform.translation.x, transform.translation.y,
                                    transform.translation.z);
  const Eigen::Matrix3d matrix = rotation.normalized().toRotationMatrix();
  for (pcd::Point& point : points->points) {
    if (!std::isfinite(point.x)) continue;
    const Eigen::Vector3d moved = matrix * Eigen::Vector3d(point.x, point.y, point.z) + translation;
    point.x = static_cast<float>(moved.x());
    point.y = static_cast<float>(moved.y());
    point.z = static_cast<float>(moved.z());
  }
}

v1::Cloud PackPoints(const pcd::Points& points) {
  std::string bytes(points.points.size() * kPackedPointBytes, '\0');
  auto* out = reinterpret_cast<std::uint8_t*>(bytes.data());
  for (const pcd::Point& point : points.points) {
    PutLittleEndian(std::bit_cast<std::uint32_t>(point.x), out);
    PutLittleEndian(std::bit_cast<std::uint32_t>(point.y), out + 4);
    PutLittleEndian(std::bit_cast<std::uint32_t>(point.z), out + 8);
    out[12] = point.r;
    out[13] = point.g;
    out[14] = point.b;
    out[15] = 0xff;
    out += kPackedPointBytes;
  }
  v1::Cloud cloud;
  v1::PackedCloud* packed = cloud.mutable_packed();
  packed->set_width(points.width);
  packed->set_height(points.height);
  packed->set_points(std::move(bytes));
  return cloud;
}

CloudMessage EncodeCloudMessage(const pcd::Points& points, const std::string& frame_id,
                                Stamp stamp) {
  CloudMessage cloud;
  cloud.frame_id = frame_id;
  cloud.stamp = stamp;
  cloud.width = points.width;
  cloud.height = points.height;
  cloud.fields = {{"x", 0, FieldType::kFloat32, 1},
                  {"y", 4, FieldType::kFloat32, 1},
                  {"z", 8, FieldType::kFloat32, 1},
                  {"rgb", 12, FieldType::kFloat32, 1}};
  cloud.point_step = 16;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.resize(points.points.size() * cloud.point_step);
  std::uint8_t* out = cloud.data.data();
  bool dense = true;
  for (const pcd::Point& point : points.points) {
    dense = dense && std::isfinite(point.x);
    PutLittleEndian(std::bit_cast<std::uint32_t>(point.x), out);
    PutLittleEndian(std::bit_cast<std::uint32_t>(point.y), out + 4);
    PutLittleEndian(std::bit_cast<std::uint32_t>(point.z), out + 8);
    PutLittleEndian((std::uint32_t{point.r} << 16) | (std::uint32_t{point.g} << 8) | point.b,
                    out + 12);
    out += cloud.point_step;
  }
  cloud.is_dense = dense;
  return cloud;
}

}  // namespace relmap::ros_bridge
