// The push primitive (see push_primitive.h).
#include "push_primitive.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>

#include "ode_math.h"
#include "point_distance.h"
#include "scene_dynamics.h"
#include "visible_motion.h"

namespace relmap::sim {
namespace {

constexpr int kDirections = 16;
// How far below the target to look for the supporting static surface (m).
constexpr double kSupportSearch = 3.0;
// The support ray starts this far above the target (a table supervoxel's
// centroid may lie a little below the table's surface).
constexpr double kSupportRayLift = 0.01;
// A support surface's normal is within 25 degrees of vertical (cos 25 = 0.906).
constexpr double kFacingUp = 0.906;
constexpr int kMaxSupportSurfaces = 8;
constexpr double kSupportStepThrough = 1e-4;  // m past a slanted surface

// What of `body`'s turns a camera cannot see (visible_motion.h), where it is now: a plain
// sphere, cylinder or capsule of one geom (ODE puts a cylinder's and a capsule's axis on
// the geom's z).
ShapeSymmetry SymmetryOf(const SimBody& body) {
  ShapeSymmetry symmetry;
  if (body.geoms.size() != 1 || TagOf(body.geoms.front()).material.texture != TextureKind::kNone) {
    return symmetry;
  }
  const dGeomID geom = body.geoms.front();
  const Eigen::Isometry3d pose = PoseOf(geom);
  symmetry.centre = pose.translation();
  switch (dGeomGetClass(geom)) {
    case dSphereClass:
      symmetry.kind = ShapeSymmetry::Kind::kAboutPoint;
      break;
    case dCylinderClass:
    case dCapsuleClass:
      symmetry.kind = ShapeSymmetry::Kind::kAboutAxis;
      symmetry.axis = pose.linear().col(2).normalized();
      break;
    default:
      break;
  }
  return symmetry;
}

// The candidate directions, as angles: evenly spaced, rotated by a random
// offset, in a random order.
std::vector<double> ApproachAngles(SeededRandom& random) {
  const double offset = random.Uniform(0, 2 * std::numbers::pi / kDirections);
  std::vector<int> order(kDirections);
  std::iota(order.begin(), order.end(), 0);
  for (int i = kDirections - 1; i > 0; --i) {  // Fisher-Yates
    std::swap(order[i], order[random.Below(static_cast<std::uint64_t>(i) + 1)]);
  }
  std::vector<double> angles;
  angles.reserve(order.size());
  for (int k : order) angles.push_back(offset + 2 * std::numbers::pi * k / kDirections);
  return angles;
}

// Moves the pusher by velocity * step for `steps` steps (fewer when `stop_on_static` and
// it touches a static body); returns the steps taken.
int MovePusher(OdeWorld& world, const Eigen::Vector3d& from, const Eigen::Vector3d& velocity,
               int steps, bool stop_on_static) {
  const double dt = world.step_seconds();
  for (int i = 0; i < steps; ++i) {
    // Position and velocity both set: the position is exact, and the contact
    // solver sees the pusher's velocity.
    const Eigen::Vector3d p = from + velocity * (i * dt);
    dBodySetPosition(world.effector(), p.x(), p.y(), p.z());
    dBodySetLinearVel(world.effector(), velocity.x(), velocity.y(), velocity.z());
    if (world.Step() && stop_on_static) return i + 1;
  }
  return steps;
}

// The height of the first static surface under `target` that faces up (a table,
// a counter, a board: something to push along), looking down from just above
// it. Slanted surfaces on the way (the flank of a fixed sphere the target lies
// on) are passed through, so that a push at them goes into them, not over them.
std::optional<double> SupportHeight(const Eigen::Vector3d& target, OdeWorld& world,
                                    RayCamera& caster) {
  Eigen::Vector3d from = target + Eigen::Vector3d(0, 0, kSupportRayLift);
  for (int surface = 0; surface < kMaxSupportSurfaces; ++surface) {
    const auto hit = caster.Cast(world, from, -Eigen::Vector3d::UnitZ(),
                                 kSupportSearch - (target.z() - from.z()), /*static_only=*/true);
    if (!hit) return std::nullopt;
    const double z = from.z() - hit->distance;
    if (hit->normal.z() > kFacingUp) return z;
    from.z() = z - kSupportStepThrough;
  }
  return std::nullopt;
}

}  // namespace

std::int32_t NearestBody(const Eigen::Vector3d& point, const std::vector<SimBody>& bodies) {
  std::int32_t nearest = kNoBody;
  double best = std::numeric_limits<double>::infinity();
  for (const SimBody& b : bodies) {
    for (dGeomID geom : b.geoms) {
      const double d = DistanceToGeom(geom, point);
      if (d < best) {
        best = d;
        nearest = b.id;
      }
    }
  }
  return nearest;
}

PushReport ExecutePush(const Eigen::Vector3d& target, double motion_threshold, OdeWorld& world,
                       const std::vector<SimBody>& bodies, RayCamera& caster,
                       SeededRandom& random) {
  PushReport report;
  if (!target.allFinite()) return report;
  report.target_body = NearestBody(target, bodies);

  const PhysicsSettings& physics = world.physics();
  const double radius = physics.effector_radius;
  Eigen::Vector3d aim = target;
  if (const auto support_z = SupportHeight(target, world, caster)) {
    aim.z() = std::max(aim.z(), *support_z + radius + physics.clearance);
  }

  Eigen::Vector3d direction, start;
  bool free = false;
  for (double angle : ApproachAngles(random)) {
    direction = Eigen::Vector3d(std::cos(angle), std::sin(angle), 0);
    start = aim - (physics.approach_distance + radius) * direction;
    world.PlaceEffector(start);
    if (!world.Collides(world.effector_geom())) {
      free = true;
      break;
    }
  }
  if (!free) {
    world.ParkEffector();
    return report;
  }
  report.executed = true;

  // ODE bodies sit at their centre of mass: the pose's translation is the centre's position.
  std::vector<Eigen::Isometry3d> before(bodies.size(), Eigen::Isometry3d::Identity());
  std::vector<ShapeSymmetry> symmetry(bodies.size());
  for (const SimBody& b : bodies) {
    if (!b.moveable) continue;
    before[b.id] = PoseOf(b.body);
    symmetry[b.id] = SymmetryOf(b);
  }
  const double dt = world.step_seconds();
  const Eigen::Vector3d velocity = physics.push_speed * direction;
  const auto planned = static_cast<int>(
      std::ceil((physics.approach_distance + physics.overshoot) / (physics.push_speed * dt)));
  const int forward = MovePusher(world, start, velocity, planned, /*stop_on_static=*/true);
  const Eigen::Vector3d reached = start + velocity * (forward * dt);
  MovePusher(world, reached, -velocity, forward, /*stop_on_static=*/false);
  world.ParkEffector();
  report.simulated_seconds = 2 * forward * dt + SettleScene(world, bodies);

  report.motion_threshold = motion_threshold;
  report.body_motions.assign(bodies.size(), Eigen::Isometry3f::Identity());
  for (const SimBody& b : bodies) {
    if (!b.moveable) continue;
    const Eigen::Isometry3d after = PoseOf(b.body);
    report.body_motions[b.id] =
        VisibleMotion(after * before[b.id].inverse(), symmetry[b.id]).cast<float>();
    if ((after.translation() - before[b.id].translation()).norm() > motion_threshold) {
      report.moved_bodies.push_back(b.id);
    }
  }
  return report;
}

}  // namespace relmap::sim
