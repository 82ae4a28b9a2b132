// OdeScene: a validated scene file built in ODE, and the SimulatedScene calls.
#include "ode_scene.h"

#include <mutex>
#include <optional>

#include "ode_bodies.h"
#include "ode_world.h"
#include "push_primitive.h"
#include "ray_camera.h"
#include "scene_dynamics.h"
#include "scene_file.h"
#include "seeded_random.h"

namespace relmap::sim {
namespace {

// Independent random streams drawn from one seed.
constexpr std::uint64_t kRespawnStream = 1;
constexpr std::uint64_t kPushStream = 2;
constexpr std::uint64_t kDepthNoiseStream = 3;

// Debian's ODE has no thread-local storage, so triangle-mesh collisions share one
// process-wide cache: scenes with meshes take this lock around ODE calls.
std::mutex& MeshCollisionMutex() {
  static std::mutex mutex;
  return mutex;
}

class OdeCall {
 public:
  explicit OdeCall(const OdeWorld& world) {
    EnsureOdeReady();
    if (world.has_meshes()) lock_.emplace(MeshCollisionMutex());
  }

 private:
  std::optional<std::lock_guard<std::mutex>> lock_;
};

}  // namespace

StatusOr<std::unique_ptr<OdeScene>> OdeScene::Load(const std::string& name_or_path,
                                                   std::uint64_t seed) {
  StatusOr<SceneFile> file = ReadSceneFile(name_or_path);
  if (!file.ok()) return file.status();
  return std::unique_ptr<OdeScene>(new OdeScene(std::move(file->scene), seed));
}

StatusOr<std::unique_ptr<OdeScene>> OdeScene::FromJson(std::string_view json,
                                                       const std::string& file_label,
                                                       std::uint64_t seed) {
  StatusOr<Scene> scene = ParseScene(json, file_label);
  if (!scene.ok()) return scene.status();
  return std::unique_ptr<OdeScene>(new OdeScene(std::move(scene).value(), seed));
}

OdeScene::OdeScene(Scene scene, std::uint64_t seed)
    : scene_(std::move(scene)),
      camera_(ResolveCamera(scene_.camera())),
      light_(ResolveLight(scene_.light())),
      motion_threshold_(MotionThreshold(scene_)),
      world_(std::make_unique<OdeWorld>(ResolvePhysics(scene_.physics()))),
      caster_(std::make_unique<RayCamera>()),
      depth_noise_(std::make_unique<SeededRandom>(seed, kDepthNoiseStream)) {
  bodies_ = BuildBodies(scene_, *world_);
  Respawn(seed);
}

OdeScene::~OdeScene() {
  OdeCall call(*world_);
  caster_.reset();
  world_.reset();
}

CameraFrame OdeScene::Capture() {
  OdeCall call(*world_);
  return caster_->Render(camera_, light_, *world_, *depth_noise_);
}

bool OdeScene::IsMoveable(std::int32_t body_id) const {
  return body_id >= 0 && body_id < body_count() && bodies_[body_id].moveable;
}

void OdeScene::Respawn(std::uint64_t seed) {
  OdeCall call(*world_);
  SeededRandom random(seed, kRespawnStream);
  last_respawn_failures_ = RespawnObjects(scene_, *world_, bodies_, random);
}

PushReport OdeScene::Push(const Eigen::Vector3f& target, std::uint64_t seed) {
  OdeCall call(*world_);
  SeededRandom random(seed, kPushStream);
  PushReport report = ExecutePush(CameraToWorld(target.cast<double>()), motion_threshold_, *world_,
                                  bodies_, *caster_, random);
  // World-frame motions to camera-frame ones: camera_from_world * motion * world_from_camera.
  const Eigen::Isometry3f world_from_camera = camera_.world_from_camera.cast<float>();
  for (Eigen::Isometry3f& motion : report.body_motions) {
    motion = world_from_camera.inverse() * motion * world_from_camera;
  }
  return report;
}

void OdeScene::SetImageSize(std::uint32_t width, std::uint32_t height) {
  camera_ = camera_.Resized(width, height);
}

std::int32_t OdeScene::body_count() const { return static_cast<std::int32_t>(bodies_.size()); }

const std::string& OdeScene::body_name(std::int32_t body_id) const {
  return bodies_.at(static_cast<std::size_t>(body_id)).name;
}

std::vector<std::int32_t> OdeScene::moveable_bodies() const {
  std::vector<std::int32_t> ids;
  for (const SimBody& b : bodies_) {
    if (b.moveable) ids.push_back(b.id);
  }
  return ids;
}

Eigen::Isometry3d OdeScene::BodyPose(std::int32_t body_id) const {
  const SimBody& b = bodies_.at(static_cast<std::size_t>(body_id));
  if (b.moveable) return ObjectPose(b);
  const Body& spec = scene_.static_bodies(body_id);
  return spec.has_pose() ? ToIsometry(spec.pose()) : Eigen::Isometry3d::Identity();
}

void OdeScene::SetObjectPose(std::int32_t body_id, const Eigen::Isometry3d& world_from_object) {
  OdeCall call(*world_);
  const SimBody& b = bodies_.at(static_cast<std::size_t>(body_id));
  if (b.moveable) PlaceObject(b, world_from_object);
}

bool OdeScene::AtRest() const { return AllAtRest(bodies_, world_->physics()); }

Eigen::Vector3d OdeScene::CameraToWorld(const Eigen::Vector3d& p) const {
  return camera_.world_from_camera * p;
}

Eigen::Vector3d OdeScene::WorldToCamera(const Eigen::Vector3d& p) const {
  return camera_.world_from_camera.inverse() * p;
}

}  // namespace relmap::sim
