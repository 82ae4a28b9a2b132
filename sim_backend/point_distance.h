// How far a point is from a geom's surface: which body a push target belongs to.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>

namespace relmap::sim {

// Distance (metres) from `point` (world) to `geom`'s solid: 0 inside. Works for
// the shapes scene files make: box, sphere, cylinder, capsule, triangle mesh
// (for a mesh, the distance to its nearest triangle).
double DistanceToGeom(dGeomID geom, const Eigen::Vector3d& point);

}  // namespace relmap::sim
