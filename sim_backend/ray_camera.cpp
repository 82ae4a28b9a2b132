// Ray casting against ODE: the nearest hit per ray, geoms tried in the order the
// ray enters their bounding boxes, then colour and shading.
#include "ray_camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ode_math.h"
#include "textures.h"

namespace relmap::sim {
namespace {

// A geom the rays may hit, with its world bounding box.
struct Candidate {
  dGeomID geom;
  Eigen::Array3d lo, hi;
};

// The enabled geoms of `world` (static ones only if asked), the pusher excluded.
std::vector<Candidate> CandidatesOf(OdeWorld& world, bool static_only) {
  std::vector<Candidate> candidates;
  const dSpaceID space = world.space();
  const int n = dSpaceGetNumGeoms(space);
  for (int i = 0; i < n; ++i) {
    const dGeomID geom = dSpaceGetGeom(space, i);
    const GeomTag& tag = TagOf(geom);
    if (!dGeomIsEnabled(geom) || tag.body_id == kNoBody || (static_only && tag.moveable)) continue;
    dReal aabb[6];
    dGeomGetAABB(geom, aabb);
    candidates.push_back({geom, {aabb[0], aabb[2], aabb[4]}, {aabb[1], aabb[3], aabb[5]}});
  }
  // Creation order, so that equal distances resolve the same way every time.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return TagOf(a.geom).order < TagOf(b.geom).order;
  });
  return candidates;
}

// Where the ray origin + t * direction, 0 <= t <= length, enters the box (slab
// test, `inverse` = 1 / direction per axis, infinite where it is 0); nullopt when
// it misses it.
std::optional<double> EntryDistance(const Candidate& box, const Eigen::Array3d& origin,
                                    const Eigen::Array3d& inverse, double length) {
  double enter = 0, leave = length;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::isinf(inverse[axis])) {
      if (origin[axis] < box.lo[axis] || origin[axis] > box.hi[axis]) return std::nullopt;
      continue;
    }
    double t0 = (box.lo[axis] - origin[axis]) * inverse[axis];
    double t1 = (box.hi[axis] - origin[axis]) * inverse[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return std::nullopt;
  }
  return enter;
}

// A candidate the ray enters, and where.
struct Entry {
  double distance;
  const Candidate* candidate;
};

// The nearest hit of `ray` set to origin + t * direction, 0 <= t <= length, among
// `candidates`. ODE's dCollide of a ray against a whole space returns the first
// contacts it finds, not the nearest; here the candidates whose boxes the ray
// enters are collided nearest entry first, until the best hit is nearer than
// the next entry. `entries` is scratch space, reused from ray to ray.
std::optional<RayHit> Nearest(dGeomID ray, const std::vector<Candidate>& candidates,
                              const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              double length, std::vector<Entry>& entries) {
  const Eigen::Array3d inverse = direction.array().inverse();
  entries.clear();
  for (const Candidate& c : candidates) {
    const auto t = EntryDistance(c, origin.array(), inverse, length);
    if (!t) continue;
    // Insertion sort: a handful of entries, and ties keep creation order.
    entries.push_back({*t, &c});
    for (std::size_t i = entries.size() - 1; i > 0 && entries[i - 1].distance > *t; --i) {
      std::swap(entries[i - 1], entries[i]);
    }
  }
  dGeomRaySetLength(ray, length);
  dGeomRaySet(ray, origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
  std::optional<RayHit> best;
  for (const Entry& entry : entries) {
    if (best && entry.distance > best->distance) break;
    dContactGeom contact;
    if (dCollide(ray, entry.candidate->geom, 1, &contact, sizeof contact) <= 0) continue;
    if (best && contact.depth >= best->distance) continue;
    best = RayHit{contact.depth,
                  Eigen::Vector3d(contact.normal[0], contact.normal[1], contact.normal[2]),
                  entry.candidate->geom};
  }
  if (best && best->normal.dot(direction) > 0) best->normal = -best->normal;
  return best;
}

std::uint8_t ToByte(double unit) {
  return static_cast<std::uint8_t>(std::clamp(unit * 255.0 + 0.5, 0.0, 255.0));
}

}  // namespace

RayCamera::RayCamera() {
  EnsureOdeReady();
  ray_ = dCreateRay(nullptr, 1.0);
  dGeomRaySetFirstContact(ray_, 0);
  dGeomRaySetClosestHit(ray_, 1);  // the nearest hit on each geom (meshes)
  dGeomRaySetBackfaceCull(ray_, 0);
}

RayCamera::~RayCamera() { dGeomDestroy(ray_); }

std::optional<RayHit> RayCamera::Cast(OdeWorld& world, const Eigen::Vector3d& origin,
                                      const Eigen::Vector3d& direction, double length,
                                      bool static_only) {
  std::vector<Entry> entries;
  return Nearest(ray_, CandidatesOf(world, static_only), origin, direction, length, entries);
}

CameraFrame RayCamera::Render(const CameraModel& camera, const LightSettings& light,
                              OdeWorld& world, SeededRandom& noise) {
  CameraFrame frame;
  frame.width = camera.width;
  frame.height = camera.height;
  const std::size_t n = static_cast<std::size_t>(camera.width) * camera.height;
  frame.points.assign(n, CameraPoint{});
  frame.body_ids.assign(n, kNoBody);
  const Eigen::Matrix3d world_from_camera = camera.world_from_camera.linear();
  const Eigen::Vector3d origin = camera.world_from_camera.translation();
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<Candidate> candidates = CandidatesOf(world, /*static_only=*/false);
  std::vector<Entry> entries;

  for (std::uint32_t v = 0; v < camera.height; ++v) {
    for (std::uint32_t u = 0; u < camera.width; ++u) {
      const std::size_t index = static_cast<std::size_t>(v) * camera.width + u;
      CameraPoint& point = frame.points[index];
      const Eigen::Vector3d ray_camera =
          Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0)
              .normalized();
      const Eigen::Vector3d ray_world = world_from_camera * ray_camera;
      const std::optional<RayHit> hit =
          Nearest(ray_, candidates, origin, ray_world, camera.max_range, entries);
      if (!hit || hit->distance < camera.min_range) {
        point.x = point.y = point.z = kNan;
        continue;
      }
      const GeomTag& tag = TagOf(hit->geom);
      frame.body_ids[index] = tag.body_id;

      const Eigen::Vector3d hit_world = origin + hit->distance * ray_world;
      const Eigen::Vector3d albedo = Albedo(tag.material, PoseOf(hit->geom).inverse() * hit_world);
      const double lit = std::max(0.0, hit->normal.dot(light.direction));
      const Eigen::Vector3d rgb = albedo * (light.ambient + (1.0 - light.ambient) * lit);
      point.r = ToByte(rgb.x());
      point.g = ToByte(rgb.y());
      point.b = ToByte(rgb.z());

      double distance = hit->distance;
      if (camera.depth_noise_sigma > 0) distance += camera.depth_noise_sigma * noise.Gaussian();
      const Eigen::Vector3f p = (distance * ray_camera).cast<float>();
      point.x = p.x();
      point.y = p.y();
      point.z = p.z();
    }
  }
  return frame;
}

}  // namespace relmap::sim
