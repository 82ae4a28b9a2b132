// The structured-light RGB-D camera (Kinect v1 / Xtion class): the ray-cast
// geometry seen through the sensor's depth noise, disparity steps, holes and
// colour noise (model and sources: kinect_noise_model.h, scene_settings.cpp).
#pragma once

#include <ode/ode.h>

#include <array>

#include "ode_world.h"
#include "scene_settings.h"
#include "seeded_random.h"
#include "simulated_scene.h"

namespace relmap::sim {

// A frame of `camera` (sensor kinect_v1) cast with `rays`, ray geoms outside any
// space: one per thread, two threads unless `world` has triangle meshes (whose
// collisions share one process-wide cache in Debian's ODE). Per pixel: the depth z of the surface
// its ray meets, laterally jittered by σL, noised by σz in the disparity domain and rounded to the
// disparity steps; a hole where nothing is met, beyond [min_range, max_range] (on z), past the
// maximum incidence angle, where the IR projector (noise.baseline along +x) does not light the
// point, or, with edge_hole_probability, on a depth edge. Colours carry a per-frame exposure and
// white balance and per-pixel noise. One draw from `noise` per frame seeds every pixel's draws, so
// equal seeds give bit-identical frames.
CameraFrame RenderStructuredLight(const CameraModel& camera, const LightSettings& light,
                                  OdeWorld& world, const std::array<dGeomID, 2>& rays,
                                  SeededRandom& noise);

}  // namespace relmap::sim
