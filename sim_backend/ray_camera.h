// The simulated RGB-D camera: one ray per pixel cast into an OdeWorld's space;
// the nearest hit gives the point, its shaded colour and its body id. The ideal
// sensor reports that exactly; the kinect_v1 sensor through its noise and holes
// (structured_light_camera.h).
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <optional>

#include "ode_world.h"
#include "ray_casting.h"
#include "scene_settings.h"
#include "seeded_random.h"
#include "simulated_scene.h"

namespace relmap::sim {

class RayCamera {
 public:
  RayCamera();  // the ray geom, outside any space, reused for every pixel
  ~RayCamera();
  RayCamera(const RayCamera&) = delete;
  RayCamera& operator=(const RayCamera&) = delete;

  // An organized frame (see simulated_scene.h) from camera.sensor: points in the
  // camera frame, colours as albedo * (ambient + (1 - ambient) max(0, n . l)),
  // NaN and kNoBody at holes. The ideal sensor's holes are where nothing is hit
  // within [min_range, max_range] along the ray, and `noise` draws its depth noise
  // when camera.depth_noise_sigma > 0; the kinect_v1 sensor draws its noise and
  // holes from `noise` too.
  CameraFrame Render(const CameraModel& camera, const LightSettings& light, OdeWorld& world,
                     SeededRandom& noise);

  // The nearest hit of the ray origin + t * direction (unit), 0 <= t <= length,
  // among enabled geoms (only static ones when `static_only`), the pusher never.
  std::optional<RayHit> Cast(OdeWorld& world, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& direction, double length, bool static_only);

 private:
  dGeomID ray_ = nullptr;
  // A second ray for the structured-light camera's second thread.
  dGeomID second_ray_ = nullptr;
};

}  // namespace relmap::sim
