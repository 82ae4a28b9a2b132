// Builds a validated scene's bodies in an OdeWorld: static bodies as geoms
// without dynamics, each copy of each object as an ODE body whose mass and
// inertia follow from its shape.
#pragma once

#include <vector>

#include "ode_world.h"
#include "scene_schema.pb.h"

namespace relmap::sim {

// Ids: static bodies 0..S-1 in file order, then every copy of every object in
// file order. Objects are created at the origin; Respawn places them.
std::vector<SimBody> BuildBodies(const Scene& scene, OdeWorld& world);

}  // namespace relmap::sim
