// Rays against an OdeWorld's geoms: the nearest hit of a ray, whether a segment
// is blocked, and the shaded colour at a hit. Shared by the ideal and the
// structured-light cameras.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ode_world.h"
#include "scene_settings.h"

namespace relmap::sim {

struct RayHit {
  double distance = 0;     // metres along the ray
  Eigen::Vector3d normal;  // unit, facing the ray's origin
  dGeomID geom = nullptr;
};

// A geom the rays may hit, with its world bounding box.
struct Candidate {
  dGeomID geom;
  Eigen::Array3d lo, hi;
};

// A candidate a ray enters, and where.
struct Entry {
  double distance;
  const Candidate* candidate;
};

// The enabled geoms of `world` (static ones only if asked), the pusher excluded,
// in creation order.
std::vector<Candidate> CandidatesOf(OdeWorld& world, bool static_only);

// The nearest hit of `ray` set to origin + t * direction (unit), 0 <= t <= length,
// among `candidates`. `entries` is scratch space, reused from ray to ray.
std::optional<RayHit> Nearest(dGeomID ray, const std::vector<Candidate>& candidates,
                              const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              double length, std::vector<Entry>& entries);

// Whether any candidate meets origin + t * direction (unit), 0 <= t <= length:
// the first hit found answers, none is sorted (shadow rays).
bool Blocked(dGeomID ray, const std::vector<Candidate>& candidates, const Eigen::Vector3d& origin,
             const Eigen::Vector3d& direction, double length);

// RGB in [0, 1] of `hit` at `hit_world`: albedo * (ambient + (1 - ambient) max(0, n . l)).
Eigen::Vector3d ShadedColour(const RayHit& hit, const Eigen::Vector3d& hit_world,
                             const LightSettings& light);

// An 8-bit channel of `unit` in [0, 1], rounded, clamped.
std::uint8_t ToByte(double unit);

}  // namespace relmap::sim
