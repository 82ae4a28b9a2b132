// Letting a scene come to rest, and placing objects in their spawn regions: the
// physics that Respawn and Push share.
#pragma once

#include <vector>

#include "ode_world.h"
#include "scene_schema.pb.h"
#include "seeded_random.h"

namespace relmap::sim {

// Whether every moveable body moves slower than the rest thresholds.
bool AllAtRest(const std::vector<SimBody>& bodies, const PhysicsSettings& physics);

// Steps until all moveable bodies have stayed at rest for 50 ms, or for at most
// physics.settle_time_cap seconds; returns the simulated seconds.
double SettleScene(OdeWorld& world, const std::vector<SimBody>& bodies);

// Every object at a pose drawn in its spawn region, redrawn (up to 2,000 times)
// while it overlaps a static body or an object already placed, then settles.
// Returns how many objects found no free pose: those are left out of the scene
// until the next respawn (disabled, far below it, never seen or touched).
int RespawnObjects(const Scene& scene, OdeWorld& world, const std::vector<SimBody>& bodies,
                   SeededRandom& random);

// The world pose of an object's frame (its shape frame in the scene file).
Eigen::Isometry3d ObjectPose(const SimBody& body);
// Puts a moveable body's object frame at `world_from_object`, at rest.
void PlaceObject(const SimBody& body, const Eigen::Isometry3d& world_from_object);

}  // namespace relmap::sim
