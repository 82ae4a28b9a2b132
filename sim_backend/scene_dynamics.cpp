// Settling and spawning.
#include "scene_dynamics.h"

#include <cmath>
#include <numbers>

#include "ode_math.h"

namespace relmap::sim {
namespace {

constexpr double kRestWindowSeconds = 0.05;
constexpr int kSpawnAttempts = 100;

void SetGeomsEnabled(const SimBody& body, bool enabled) {
  for (dGeomID geom : body.geoms) {
    if (enabled) {
      dGeomEnable(geom);
    } else {
      dGeomDisable(geom);
    }
  }
}

bool Overlaps(OdeWorld& world, const SimBody& body) {
  for (dGeomID geom : body.geoms) {
    if (world.Collides(geom)) return true;
  }
  return false;
}

Eigen::Isometry3d DrawPose(const SpawnRegion& spawn, SeededRandom& random) {
  const Eigen::Matrix3d base = RotationFromRpyDeg(spawn.base_rpy_deg());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  switch (ResolveSpawnOrientation(spawn)) {
    case SpawnOrientation::kYaw:
      pose.linear() =
          Eigen::AngleAxisd(random.Uniform(0, 2 * std::numbers::pi), Eigen::Vector3d::UnitZ()) *
          base;
      break;
    case SpawnOrientation::kFull:
      pose.linear() = random.Rotation().toRotationMatrix();
      break;
    case SpawnOrientation::kFixed:
      pose.linear() = base;
      break;
  }
  pose.translation() = Eigen::Vector3d(random.Uniform(spawn.min().x(), spawn.max().x()),
                                       random.Uniform(spawn.min().y(), spawn.max().y()),
                                       random.Uniform(spawn.min().z(), spawn.max().z()));
  return pose;
}

}  // namespace

bool AllAtRest(const std::vector<SimBody>& bodies, const PhysicsSettings& physics) {
  for (const SimBody& b : bodies) {
    if (!b.moveable) continue;
    const dReal* v = dBodyGetLinearVel(b.body);
    const dReal* w = dBodyGetAngularVel(b.body);
    if (Eigen::Vector3d(v[0], v[1], v[2]).norm() > physics.rest_linear_speed ||
        Eigen::Vector3d(w[0], w[1], w[2]).norm() > physics.rest_angular_speed) {
      return false;
    }
  }
  return true;
}

double SettleScene(OdeWorld& world, const std::vector<SimBody>& bodies) {
  const PhysicsSettings& physics = world.physics();
  const auto window = static_cast<int>(std::ceil(kRestWindowSeconds / world.step_seconds()));
  const auto cap = static_cast<int>(std::ceil(physics.settle_time_cap / world.step_seconds()));
  int steps = 0;
  for (int resting = 0; steps < cap && resting < window; ++steps) {
    world.Step();
    resting = AllAtRest(bodies, physics) ? resting + 1 : 0;
  }
  return steps * world.step_seconds();
}

int RespawnObjects(const Scene& scene, OdeWorld& world, const std::vector<SimBody>& bodies,
                   SeededRandom& random) {
  for (const SimBody& b : bodies) {
    if (b.moveable) SetGeomsEnabled(b, false);
  }
  int failures = 0;
  for (const SimBody& b : bodies) {
    if (!b.moveable) continue;
    const SpawnRegion& spawn = scene.objects(b.object_index).spawn();
    bool placed = false;
    for (int attempt = 0; attempt < kSpawnAttempts && !placed; ++attempt) {
      PlaceObject(b, DrawPose(spawn, random));
      SetGeomsEnabled(b, true);
      placed = !Overlaps(world, b);
      if (!placed && attempt + 1 < kSpawnAttempts) SetGeomsEnabled(b, false);
    }
    if (!placed) ++failures;
  }
  SettleScene(world, bodies);
  return failures;
}

Eigen::Isometry3d ObjectPose(const SimBody& body) {
  return PoseOf(body.body) * body.body_from_object;
}

void PlaceObject(const SimBody& body, const Eigen::Isometry3d& world_from_object) {
  SetPoseAtRest(body.body, world_from_object * body.body_from_object.inverse());
}

}  // namespace relmap::sim
