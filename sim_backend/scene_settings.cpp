// Defaults and unit conversions of scene files (see scene_schema.proto).
#include "scene_settings.h"

#include <cmath>

namespace relmap::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;
// Kinect v1 (the paper's sensor): fx = fy = 525 px at 640 px wide.
constexpr double kKinectFocalAt640 = 525.0;

Rgb8 ToRgb8(const Rgb& c) {
  return {static_cast<std::uint8_t>(c.r()), static_cast<std::uint8_t>(c.g()),
          static_cast<std::uint8_t>(c.b())};
}

// The camera's rotation (columns: its x right, y down, z forward in the world).
Eigen::Matrix3d CameraRotation(const Camera& camera) {
  if (camera.has_look_at()) {
    const Eigen::Vector3d up =
        camera.has_up() ? ToEigen(camera.up()).normalized() : Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d forward =
        (ToEigen(camera.look_at()) - ToEigen(camera.position())).normalized();
    const Eigen::Vector3d right = forward.cross(up).normalized();
    Eigen::Matrix3d r;
    r.col(0) = right;
    r.col(1) = forward.cross(right);
    r.col(2) = forward;
    return r;
  }
  // The reference camera looks along world +x with image right = -y, down = -z.
  Eigen::Matrix3d reference;
  reference.col(0) = -Eigen::Vector3d::UnitY();
  reference.col(1) = -Eigen::Vector3d::UnitZ();
  reference.col(2) = Eigen::Vector3d::UnitX();
  return RotationFromRpyDeg(camera.rpy_deg()) * reference;
}

}  // namespace

CameraModel CameraModel::Resized(std::uint32_t new_width, std::uint32_t new_height) const {
  CameraModel resized = *this;
  const double sx = static_cast<double>(new_width) / width;
  const double sy = static_cast<double>(new_height) / height;
  resized.width = new_width;
  resized.height = new_height;
  resized.fx = fx * sx;
  resized.fy = fy * sy;
  // Pixel centres sit at integer coordinates: scale about the image's corner,
  // which is at -0.5.
  resized.cx = (cx + 0.5) * sx - 0.5;
  resized.cy = (cy + 0.5) * sy - 0.5;
  return resized;
}

Eigen::Vector3d ToEigen(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Eigen::Matrix3d RotationFromRpyDeg(const Vec3& rpy_deg) {
  return (Eigen::AngleAxisd(rpy_deg.z() * kRadiansPerDegree, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy_deg.y() * kRadiansPerDegree, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy_deg.x() * kRadiansPerDegree, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d ToIsometry(const Pose& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = RotationFromRpyDeg(pose.rpy_deg());
  t.translation() = ToEigen(pose.position());
  return t;
}

CameraModel ResolveCamera(const Camera& camera) {
  CameraModel model;
  model.width = camera.has_width() ? camera.width() : 320;
  model.height = camera.has_height() ? camera.height() : 240;
  if (camera.has_fx()) {
    model.fx = camera.fx();
  } else if (camera.has_horizontal_fov_deg()) {
    model.fx = 0.5 * model.width / std::tan(0.5 * camera.horizontal_fov_deg() * kRadiansPerDegree);
  } else {
    model.fx = kKinectFocalAt640 * model.width / 640.0;
  }
  model.fy = camera.has_fy() ? camera.fy() : model.fx;
  model.cx = camera.has_cx() ? camera.cx() : 0.5 * (model.width - 1.0);
  model.cy = camera.has_cy() ? camera.cy() : 0.5 * (model.height - 1.0);
  model.world_from_camera.linear() = CameraRotation(camera);
  model.world_from_camera.translation() = ToEigen(camera.position());
  model.depth_noise_sigma = camera.has_depth_noise_sigma() ? camera.depth_noise_sigma() : 0.0;
  model.min_range = camera.has_min_range() ? camera.min_range() : 0.0;
  model.max_range = camera.has_max_range() ? camera.max_range() : 4.0;
  return model;
}

LightSettings ResolveLight(const Light& light) {
  LightSettings settings;
  if (light.has_direction()) settings.direction = ToEigen(light.direction());
  settings.direction.normalize();
  if (light.has_ambient()) settings.ambient = light.ambient();
  return settings;
}

PhysicsSettings ResolvePhysics(const Physics& p) {
  PhysicsSettings s;
  if (p.has_step_hz()) s.step_hz = p.step_hz();
  if (p.has_gravity()) s.gravity = p.gravity();
  if (p.has_effector_radius()) s.effector_radius = p.effector_radius();
  if (p.has_approach_distance()) s.approach_distance = p.approach_distance();
  if (p.has_overshoot()) s.overshoot = p.overshoot();
  if (p.has_push_speed()) s.push_speed = p.push_speed();
  if (p.has_clearance()) s.clearance = p.clearance();
  if (p.has_rest_linear_speed()) s.rest_linear_speed = p.rest_linear_speed();
  if (p.has_rest_angular_speed_deg()) {
    s.rest_angular_speed = p.rest_angular_speed_deg() * kRadiansPerDegree;
  }
  if (p.has_settle_time_cap()) s.settle_time_cap = p.settle_time_cap();
  return s;
}

Material ResolveMaterial(const Body& body, const Material* parent) {
  Material m = parent != nullptr ? *parent : Material{};
  if (body.has_color()) {
    m.color = ToRgb8(body.color());
    m.texture = TextureKind::kNone;  // a part's own colour starts without the parent's texture
  }
  if (body.has_texture()) {
    const Texture& t = body.texture();
    const bool wood = t.kind() == "wood";
    m.texture = wood ? TextureKind::kWood : TextureKind::kChecker;
    if (t.has_color()) {
      m.texture_color = ToRgb8(t.color());
    } else {
      for (int i = 0; i < 3; ++i) m.texture_color[i] = static_cast<std::uint8_t>(m.color[i] * 0.6);
    }
    m.texture_scale = t.has_scale() ? t.scale() : (wood ? 0.012 : 0.05);
  }
  if (body.has_friction()) m.friction = body.friction();
  if (body.has_rolling_friction()) m.rolling_friction = body.rolling_friction();
  return m;
}

SpawnOrientation ResolveSpawnOrientation(const SpawnRegion& spawn) {
  if (spawn.orientation() == "full") return SpawnOrientation::kFull;
  if (spawn.orientation() == "fixed") return SpawnOrientation::kFixed;
  return SpawnOrientation::kYaw;
}

double MotionThreshold(const Scene& scene) {
  return scene.has_motion_threshold() ? scene.motion_threshold() : 0.01;
}

std::uint32_t ObjectCount(const Body& object) { return object.has_count() ? object.count() : 1; }

}  // namespace relmap::sim
