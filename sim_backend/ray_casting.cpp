// Ray casting against ODE: the nearest hit per ray, geoms tried in the order the
// ray enters their bounding boxes; shadow rays stop at the first hit.
#include "ray_casting.h"

#include <algorithm>
#include <cmath>

#include "ode_math.h"
#include "textures.h"

namespace relmap::sim {
namespace {

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

void Aim(dGeomID ray, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
         double length) {
  dGeomRaySetLength(ray, length);
  dGeomRaySet(ray, origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
}

}  // namespace

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

// ODE's dCollide of a ray against a whole space returns the first contacts it
// finds, not the nearest; here the candidates whose boxes the ray enters are
// collided nearest entry first, until the best hit is nearer than the next entry.
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
  Aim(ray, origin, direction, length);
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

bool Blocked(dGeomID ray, const std::vector<Candidate>& candidates, const Eigen::Vector3d& origin,
             const Eigen::Vector3d& direction, double length) {
  const Eigen::Array3d inverse = direction.array().inverse();
  bool aimed = false;
  for (const Candidate& c : candidates) {
    if (!EntryDistance(c, origin.array(), inverse, length)) continue;
    if (!aimed) Aim(ray, origin, direction, length);
    aimed = true;
    dContactGeom contact;
    if (dCollide(ray, c.geom, 1, &contact, sizeof contact) > 0) return true;
  }
  return false;
}

Eigen::Vector3d ShadedColour(const RayHit& hit, const Eigen::Vector3d& hit_world,
                             const LightSettings& light) {
  const Eigen::Vector3d albedo =
      Albedo(TagOf(hit.geom).material, PoseOf(hit.geom).inverse() * hit_world);
  const double lit = std::max(0.0, hit.normal.dot(light.direction));
  return albedo * (light.ambient + (1.0 - light.ambient) * lit);
}

std::uint8_t ToByte(double unit) {
  return static_cast<std::uint8_t>(std::clamp(unit * 255.0 + 0.5, 0.0, 255.0));
}

}  // namespace relmap::sim
