// What the experiment runner needs from a simulated world: a camera frame with the
// body behind every pixel, which bodies are moveable, a re-spawn for the paper's
// simplified (oracle) setup, and a push for the physical mode. The ODE world
// implements it (ode_scene.h); tests may implement it with analytic geometry.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "kinect_noise_model.h"

namespace relmap::sim {

// One pixel of the simulated RGB-D camera, in the camera frame (x right, y down,
// z forward, metres, as a Kinect's clouds are); a ray that hits nothing is a hole
// (NaN x, y, z).
struct CameraPoint {
  float x = 0, y = 0, z = 0;
  std::uint8_t r = 0, g = 0, b = 0;
};

// An organized frame, row-major, and per pixel the id of the body its ray hit
// (kNoBody for a hole).
inline constexpr std::int32_t kNoBody = -1;
struct CameraFrame {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<CameraPoint> points;
  std::vector<std::int32_t> body_ids;
};

// What a push did, from the simulator's point of view (ground truth, never sent
// to the server).
struct PushReport {
  // Whether the end-effector reached its start pose: false when every approach
  // direction tried was blocked (the push did not happen).
  bool executed = false;
  // The body whose surface was nearest the target point (kNoBody if none).
  std::int32_t target_body = kNoBody;
  // Bodies whose centre of mass moved by more than the scene's motion threshold.
  std::vector<std::int32_t> moved_bodies;
  // Simulated seconds, pushing and settling.
  double simulated_seconds = 0;
  // Per body id, its rigid motion over the push in the camera frame, as a camera sees it:
  // a point p of body b before the push is at body_motions[b] * p after it, less a turn
  // the body's shape and colour hide (a plain ball's about its centre: visible_motion.h);
  // identity for static bodies. Empty when the push was not executed.
  std::vector<Eigen::Isometry3f> body_motions;
  // The scene's motion threshold (m), by which a point counts as displaced.
  double motion_threshold = 0;
};

class SimulatedScene {
 public:
  virtual ~SimulatedScene() = default;

  // The scene's name (its file's `name`).
  virtual const std::string& name() const = 0;
  // Renders the scene from its camera.
  virtual CameraFrame Capture() = 0;
  // Whether `body_id` (as in CameraFrame::body_ids) belongs to a moveable object.
  virtual bool IsMoveable(std::int32_t body_id) const = 0;
  // The paper's simplified setup: every moveable object at a random collision-free
  // pose in its spawn region, drawn from `seed`, then settled.
  virtual void Respawn(std::uint64_t seed) = 0;
  // Objects the last Respawn found no free pose for and left out of the scene
  // (usually 0; a crowded spawn region makes it more).
  virtual int last_respawn_failures() const { return 0; }
  // The paper's push at `target` (camera frame, metres; a supervoxel's centroid):
  // approach from a random collision-free direction drawn from `seed`, 5 cm
  // straight to the target and a few cm further, retreat, and let the scene settle.
  virtual PushReport Push(const Eigen::Vector3f& target, std::uint64_t seed) = 0;
  // The depth noise of the camera, for the change detector to judge depths by; nullptr for
  // an ideal camera (the server's defaults then, a Kinect v1's).
  virtual const KinectNoiseModel* depth_noise() const { return nullptr; }
  // The distance (m) by which a point or body counts as moved (PushReport::motion_threshold).
  virtual double motion_threshold() const = 0;
};

}  // namespace relmap::sim
