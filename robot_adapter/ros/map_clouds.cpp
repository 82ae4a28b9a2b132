// The maps' clouds carry only the segmented points: the rest of the scene is the input
// cloud, which RViz shows on its own.
#include "map_clouds.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace relmap::ros_bridge {
namespace {

constexpr std::uint32_t kMapPointBytes = 24;  // x y z rgb intensity (float32), supervoxel (uint32)

void PutUint32(std::uint32_t value, std::uint8_t* out) {
  for (int byte = 0; byte < 4; ++byte) out[byte] = static_cast<std::uint8_t>(value >> (8 * byte));
}

void PutFloat(float value, std::uint8_t* out) {
  PutUint32(std::bit_cast<std::uint32_t>(value), out);
}

}  // namespace

StatusOr<CloudMessage> MapCloud(const pcd::Points& sent, const v1::ComputeMapsResponse& maps,
                                client::MapKind kind, const std::string& frame_id, Stamp stamp) {
  std::vector<image::ColouredPoint> own(sent.points.size());
  for (std::size_t i = 0; i < own.size(); ++i) {
    const pcd::Point& p = sent.points[i];
    own[i] = {p.x, p.y, p.z, {p.r, p.g, p.b}};
  }
  StatusOr<std::vector<image::ColouredPoint>> coloured =
      client::ColourPoints(sent.width, sent.height, own, maps, kind);
  if (!coloured.ok()) return coloured.status();

  std::unordered_map<std::int32_t, float> intensity_of;
  for (const v1::Supervoxel& s : maps.supervoxels()) {
    intensity_of[static_cast<std::int32_t>(s.id())] =
        static_cast<float>(kind == client::MapKind::kRelevance ? s.relevance() : s.choice());
  }
  CloudMessage cloud;
  cloud.frame_id = frame_id;
  cloud.stamp = stamp;
  cloud.fields = {
      {"x", 0, FieldType::kFloat32, 1},          {"y", 4, FieldType::kFloat32, 1},
      {"z", 8, FieldType::kFloat32, 1},          {"rgb", 12, FieldType::kFloat32, 1},
      {"intensity", 16, FieldType::kFloat32, 1}, {"supervoxel", 20, FieldType::kUint32, 1}};
  cloud.point_step = kMapPointBytes;
  cloud.is_dense = true;
  const auto& labels = maps.point_labels();
  for (std::size_t i = 0; i < coloured->size(); ++i) {
    const std::int32_t label = labels[static_cast<int>(i)];
    const image::ColouredPoint& p = (*coloured)[i];
    // A labelled point is finite: the server segments only finite points.
    if (label < 0 || !std::isfinite(p.x)) continue;
    const std::size_t at = cloud.data.size();
    cloud.data.resize(at + kMapPointBytes);
    std::uint8_t* out = cloud.data.data() + at;
    PutFloat(p.x, out);
    PutFloat(p.y, out + 4);
    PutFloat(p.z, out + 8);
    PutUint32((std::uint32_t{p.colour[0]} << 16) | (std::uint32_t{p.colour[1]} << 8) | p.colour[2],
              out + 12);
    PutFloat(intensity_of.at(label), out + 16);
    PutUint32(static_cast<std::uint32_t>(label), out + 20);
  }
  cloud.width = static_cast<std::uint32_t>(cloud.data.size() / kMapPointBytes);
  cloud.height = 1;
  cloud.row_step = cloud.width * kMapPointBytes;
  return cloud;
}

Quaternion RotationFromXAxis(Vector3d direction) {
  const double norm =
      std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
  if (!(norm > 0) || !std::isfinite(norm)) return {};
  const double dx = direction.x / norm, dy = direction.y / norm, dz = direction.z / norm;
  // The half-way quaternion: axis x × d, angle acos(x · d), as (x × d, 1 + x · d)
  // normalised; undefined for d = −x, where any axis perpendicular to x serves.
  const double w = 1.0 + dx;
  if (w < 1e-9) return {0, 0, 1, 0};
  const double qx = 0, qy = -dz, qz = dy;
  const double length = std::sqrt(qx * qx + qy * qy + qz * qz + w * w);
  return {qx / length, qy / length, qz / length, w / length};
}

std::optional<TargetPose> TargetOf(const v1::ComputeMapsResponse& maps, const std::string& frame_id,
                                   Stamp stamp) {
  if (!maps.has_target_supervoxel_id()) return std::nullopt;
  for (const v1::Supervoxel& s : maps.supervoxels()) {
    if (s.id() != maps.target_supervoxel_id()) continue;
    TargetPose pose;
    pose.frame_id = frame_id;
    pose.stamp = stamp;
    pose.position = {s.centroid().x(), s.centroid().y(), s.centroid().z()};
    pose.normal = {s.normal().x(), s.normal().y(), s.normal().z()};
    pose.orientation = RotationFromXAxis(pose.normal);
    pose.supervoxel_id = s.id();
    return pose;
  }
  return std::nullopt;
}

}  // namespace relmap::ros_bridge
