// Settling and spawning.
#include "scene_dynamics.h"

#include <cmath>
#include <numbers>

#include "ode_math.h"

namespace relmap::sim {
namespace {

constexpr double kRestWindowSeconds = 0.05;
// Draws per object before it is left out. The benchmark scenes' spawn regions are
// crowded with fixed objects: at 100 draws a third to a half of their objects found
// no free pose (ShelfClutter 103 and Workbench 131 of 264 placements, 22 respawns
// each); at 2,000 all but a few do. A draw is one collision query, microseconds.
constexpr int kSpawnAttempts = 2000;
// Where an object left out of a respawn waits, far below everything and out of sight.
constexpr double kLeftOutDepth = -2000.0;

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

// An object that found no free pose sits out this respawn: its geoms stay disabled
// (no contact, no ray hits it) and its body does not move. Left where it overlapped,
// as before, the solver ejected it at 3-15 m/s off the table, through the other
// objects and on into a fall that held every settle to its 3 s cap.
void LeaveOut(const SimBody& body) {
  SetGeomsEnabled(body, false);
  SetPoseAtRest(body.body, Eigen::Isometry3d(Eigen::Translation3d(0, 0, kLeftOutDepth)));
  dBodyDisable(body.body);
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
    dBodyEnable(b.body);
    bool placed = false;
    for (int attempt = 0; attempt < kSpawnAttempts && !placed; ++attempt) {
      PlaceObject(b, DrawPose(spawn, random));
      SetGeomsEnabled(b, true);
      placed = !Overlaps(world, b);
      if (!placed) SetGeomsEnabled(b, false);
    }
    if (!placed) {
      LeaveOut(b);
      ++failures;
    }
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
