// A validated scene file's tunables with their defaults filled in: the one place
// that knows the defaults of the camera, the light, the physics and the
// materials, and the conversions from the schema's units (degrees) to the code's
// (radians, Eigen types).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>

#include "kinect_noise_model.h"
#include "scene_schema.pb.h"

namespace relmap::sim {

using Rgb8 = std::array<std::uint8_t, 3>;

enum class TextureKind { kNone, kWood, kChecker };

// What a shape looks like and how it touches others.
struct Material {
  Rgb8 color{};
  TextureKind texture = TextureKind::kNone;
  Rgb8 texture_color{};             // wood late-wood / alternate checker squares
  double texture_scale = 0;         // metres
  double friction = 0.6;            // Coulomb coefficient
  double rolling_friction = 0.001;  // metres (lever arm of the normal force)
};

enum class Sensor {
  kIdeal,     // the exact depth along each ray
  kKinectV1,  // the structured-light model (structured_light_camera.h)
};

// The structured-light camera's failures and colour, beside its depth noise
// (angles in radians, pixels at the sensor's native width).
struct StructuredLightSettings {
  double max_incidence = 0;           // rad: steeper surfaces are holes
  double edge_disparity_jump_px = 0;  // per native pixel of separation
  double edge_hole_probability = 0;
  double color_noise_sigma = 0;  // 8-bit levels
  double exposure_sigma = 0;
  double white_balance_sigma = 0;
};

// The Kinect v1's figures (values and sources in scene_settings.cpp).
KinectNoiseModel DefaultKinectNoise();
StructuredLightSettings DefaultStructuredLight();

// A pinhole camera: intrinsics in pixels, pose as world_from_camera (camera frame
// x right, y down, z forward).
struct CameraModel {
  std::uint32_t width = 320;
  std::uint32_t height = 240;
  double fx = 262.5, fy = 262.5, cx = 159.5, cy = 119.5;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  Sensor sensor = Sensor::kKinectV1;
  double depth_noise_sigma = 0;  // ideal only: metres along the ray
  double min_range = 0;          // metres (ideal: along the ray; kinect_v1: depth z)
  double max_range = 4.0;        // metres
  // kinect_v1 only. The IR projector sits noise.baseline along the camera's +x.
  KinectNoiseModel noise = DefaultKinectNoise();
  StructuredLightSettings structured_light = DefaultStructuredLight();

  // The same field of view at another image size.
  CameraModel Resized(std::uint32_t new_width, std::uint32_t new_height) const;
};

struct LightSettings {
  Eigen::Vector3d direction{-0.4, 0.3, 1.0};  // unit, towards the light, world frame
  double ambient = 0.35;
};

struct PhysicsSettings {
  double step_hz = 1000;
  double gravity = 9.81;
  double effector_radius = 0.01;
  double approach_distance = 0.05;
  double overshoot = 0.03;
  double push_speed = 0.15;
  double clearance = 0.005;
  double rest_linear_speed = 0.005;
  double rest_angular_speed = 3.0 * 3.14159265358979323846 / 180.0;  // rad/s
  double settle_time_cap = 3.0;
};

enum class SpawnOrientation { kYaw, kFull, kFixed };

Eigen::Vector3d ToEigen(const Vec3& v);
// R = Rz(yaw) * Ry(pitch) * Rx(roll), angles in degrees.
Eigen::Matrix3d RotationFromRpyDeg(const Vec3& rpy_deg);
Eigen::Isometry3d ToIsometry(const Pose& pose);

CameraModel ResolveCamera(const Camera& camera);
LightSettings ResolveLight(const Light& light);
PhysicsSettings ResolvePhysics(const Physics& physics);
// `body`'s material; a part without a colour takes `parent`'s look (not its
// friction, which is the part's own or the parent's when unset).
Material ResolveMaterial(const Body& body, const Material* parent = nullptr);
SpawnOrientation ResolveSpawnOrientation(const SpawnRegion& spawn);
double MotionThreshold(const Scene& scene);
std::uint32_t ObjectCount(const Body& object);

}  // namespace relmap::sim
