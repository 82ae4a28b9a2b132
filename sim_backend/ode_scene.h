// The simulated world of relmap-sim: a scene file's table and objects in ODE,
// seen by a ray-cast RGB-D camera and pushed by a kinematic pusher.
//
// Frames and units: the world frame is the scene file's (z up, metres); the
// camera frame is x right, y down, z forward (camera().world_from_camera maps it
// to the world). Push targets and frame points are in the camera frame.
//
// Threads: an OdeScene is used by one thread at a time; different OdeScenes may
// run on different threads at once (each has its own ODE world, space and step
// threading). Scenes with triangle meshes share Debian ODE's process-wide mesh
// collision cache, so their calls are serialised by a process-wide lock. The
// kinect_v1 camera's Capture renders on a second thread of its own, except in
// scenes with meshes (structured_light_camera.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"
#include "scene_schema.pb.h"
#include "scene_settings.h"
#include "simulated_scene.h"

namespace relmap::sim {

class OdeWorld;
class RayCamera;
class SeededRandom;
struct SimBody;

class OdeScene final : public SimulatedScene {
 public:
  // A shipped scene by name (e.g. "MoveableBalls") or a scene file by path; its
  // objects respawned with `seed`, which also seeds the camera's noise.
  // NotFound / InvalidArgument (naming the file and field) on a bad scene.
  static StatusOr<std::unique_ptr<OdeScene>> Load(const std::string& name_or_path,
                                                  std::uint64_t seed);
  // The same from a scene file's text; `file_label` names it in errors.
  static StatusOr<std::unique_ptr<OdeScene>> FromJson(std::string_view json,
                                                      const std::string& file_label,
                                                      std::uint64_t seed);
  ~OdeScene() override;

  const std::string& name() const override { return scene_.name(); }
  CameraFrame Capture() override;
  bool IsMoveable(std::int32_t body_id) const override;
  void Respawn(std::uint64_t seed) override;
  // `target` in the camera frame; see push_primitive.h for the motion.
  PushReport Push(const Eigen::Vector3f& target, std::uint64_t seed) override;

  // The scene file as parsed.
  const Scene& scene() const { return scene_; }
  // Intrinsics (pixels) and pose (world_from_camera) of the camera.
  const CameraModel& camera() const { return camera_; }
  const KinectNoiseModel* depth_noise() const override {
    return camera_.sensor == Sensor::kKinectV1 ? &camera_.noise : nullptr;
  }
  double motion_threshold() const override { return motion_threshold_; }
  // Renders at another size with the same field of view.
  void SetImageSize(std::uint32_t width, std::uint32_t height);

  // Bodies: ids 0..body_count()-1, static bodies first (file order), then each
  // copy of each object.
  std::int32_t body_count() const;
  // The scene file's name for the body (copies get "#k"), e.g. "blue ball#2".
  const std::string& body_name(std::int32_t body_id) const;
  std::vector<std::int32_t> moveable_bodies() const;
  // The world pose of a body's frame as the scene file defines it (an object's
  // shape frame, not its centre of mass).
  Eigen::Isometry3d BodyPose(std::int32_t body_id) const;
  // Puts a moveable body at `world_from_object`, at rest (for tests and tools).
  void SetObjectPose(std::int32_t body_id, const Eigen::Isometry3d& world_from_object);
  // Whether every moveable body moves slower than the scene's rest thresholds.
  bool AtRest() const;
  int last_respawn_failures() const override { return last_respawn_failures_; }

  Eigen::Vector3d CameraToWorld(const Eigen::Vector3d& p) const;
  Eigen::Vector3d WorldToCamera(const Eigen::Vector3d& p) const;

 private:
  OdeScene(Scene scene, std::uint64_t seed);

  Scene scene_;
  CameraModel camera_;
  LightSettings light_;
  double motion_threshold_;
  std::unique_ptr<OdeWorld> world_;
  std::unique_ptr<RayCamera> caster_;
  std::vector<SimBody> bodies_;
  std::unique_ptr<SeededRandom> depth_noise_;
  int last_respawn_failures_ = 0;
};

}  // namespace relmap::sim
