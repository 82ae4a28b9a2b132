// Surface colour of a material at a point: its plain colour, or a procedural
// texture (wood grain, checker) evaluated in the shape's own frame.
#pragma once

#include <Eigen/Core>

#include "scene_settings.h"

namespace relmap::sim {

// The albedo (RGB in [0, 1]) of `material` at `local`, a point in the shape's
// frame, metres.
Eigen::Vector3d Albedo(const Material& material, const Eigen::Vector3d& local);

}  // namespace relmap::sim
