// The paper's push with a kinematic spherical pusher: approach from a random
// collision-free horizontal direction, 5 cm straight to the target and a few cm
// further, retreat, settle.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "ode_world.h"
#include "ray_camera.h"
#include "seeded_random.h"
#include "simulated_scene.h"

namespace relmap::sim {

// Pushes at `target` (world frame, metres). The pusher's centre starts
// approach_distance + radius before the target, at the target's height but at
// least radius + clearance above the static surface under the target, and moves
// approach_distance + overshoot at push_speed (so its front passes the target by
// `overshoot`), stopping early if it runs into a static body; then it goes back
// the same way, leaves, and the scene settles. The direction is the first
// collision-free one of 16 evenly spaced horizontal directions, randomly rotated
// and shuffled by `random`. The report's body motions are in the world frame.
PushReport ExecutePush(const Eigen::Vector3d& target, double motion_threshold, OdeWorld& world,
                       const std::vector<SimBody>& bodies, RayCamera& caster, SeededRandom& random);

// The body whose solid is nearest `point` (kNoBody when there are no bodies).
std::int32_t NearestBody(const Eigen::Vector3d& point, const std::vector<SimBody>& bodies);

}  // namespace relmap::sim
