// Defaults and unit conversions of scene files (see scene_schema.proto).
#include "scene_settings.h"

#include <cmath>
#include <numbers>

namespace relmap::sim {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
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

constexpr double kKinectMinRange = 0.5;  // metres, a Kinect v1's near limit
constexpr double kMaxRange = 4.0;        // metres, a Kinect v1's far limit

KinectNoiseModel ResolveNoise(const SensorNoise& n) {
  KinectNoiseModel m = DefaultKinectNoise();
  if (n.has_axial_constant()) m.axial_constant = n.axial_constant();
  if (n.has_axial_quadratic()) m.axial_quadratic = n.axial_quadratic();
  if (n.has_axial_offset()) m.axial_offset = n.axial_offset();
  if (n.has_axial_grazing()) m.axial_grazing = n.axial_grazing();
  if (n.has_lateral_constant_px()) m.lateral_constant_px = n.lateral_constant_px();
  if (n.has_lateral_grazing_px()) m.lateral_grazing_px = n.lateral_grazing_px();
  if (n.has_ir_focal_px()) m.ir_focal_px = n.ir_focal_px();
  if (n.has_baseline()) m.baseline = n.baseline();
  if (n.has_disparity_steps_per_px()) m.disparity_steps_per_px = n.disparity_steps_per_px();
  return m;
}

StructuredLightSettings ResolveStructuredLight(const SensorNoise& n) {
  StructuredLightSettings s = DefaultStructuredLight();
  if (n.has_max_incidence_deg()) s.max_incidence = n.max_incidence_deg() * kRadiansPerDegree;
  if (n.has_edge_disparity_jump_px()) s.edge_disparity_jump_px = n.edge_disparity_jump_px();
  if (n.has_edge_hole_probability()) s.edge_hole_probability = n.edge_hole_probability();
  if (n.has_color_noise_sigma()) s.color_noise_sigma = n.color_noise_sigma();
  if (n.has_exposure_sigma()) s.exposure_sigma = n.exposure_sigma();
  if (n.has_white_balance_sigma()) s.white_balance_sigma = n.white_balance_sigma();
  return s;
}

}  // namespace

KinectNoiseModel DefaultKinectNoise() {
  return {
      // Nguyen, Izadi & Lovell 2012 (3DIMPVT), the axial fit for 10° < θ < 60°
      // and its grazing-angle term, and the lateral fit, at 640 x 480.
      .axial_constant = 0.0012,
      .axial_quadratic = 0.0019,
      .axial_offset = 0.4,
      .axial_grazing = 0.0001,
      .lateral_constant_px = 0.8,
      .lateral_grazing_px = 0.035,
      // Khoshelham & Elberink 2012 (Sensors 12:1437): IR focal length ~580 px,
      // baseline ~7.5 cm, disparity in 1/8 px: steps z² / 348 m, 7.2 cm at 5 m.
      .ir_focal_px = 580.0,
      .baseline = 0.075,
      .disparity_steps_per_px = 8.0,
      .reference_width_px = 640.0,
  };
}

StructuredLightSettings DefaultStructuredLight() {
  return {
      // Nguyen et al.'s σz grows without bound as θ nears 90° (×25 at 75°): the
      // block matcher finds no pattern there; past 75° the sensor returns nothing.
      .max_incidence = 75.0 * kRadiansPerDegree,
      // A plane tilted to 75° at 0.5 m changes disparity by b tan θ / z = 0.56 px
      // per pixel, a 5 cm step at 1 m by 2.9 px: 1 px separates edges from slopes
      // over the whole working range.
      .edge_disparity_jump_px = 1.0,
      // The correlation window straddling an edge matches either side or neither:
      // edge pixels drop out in about half the frames, so edges flicker and fray.
      .edge_hole_probability = 0.5,
      // Not from a paper: a few levels of sensor noise and a few per cent of
      // auto-exposure and white-balance drift, as a consumer webcam shows.
      .color_noise_sigma = 2.0,
      .exposure_sigma = 0.03,
      .white_balance_sigma = 0.02,
  };
}

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
  model.sensor = camera.sensor() == "ideal" ? Sensor::kIdeal : Sensor::kKinectV1;
  const bool ideal = model.sensor == Sensor::kIdeal;
  model.depth_noise_sigma = camera.has_depth_noise_sigma() ? camera.depth_noise_sigma() : 0.0;
  model.min_range = camera.has_min_range() ? camera.min_range() : (ideal ? 0.0 : kKinectMinRange);
  model.max_range = camera.has_max_range() ? camera.max_range() : kMaxRange;
  model.noise = ResolveNoise(camera.sensor_noise());
  model.structured_light = ResolveStructuredLight(camera.sensor_noise());
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
