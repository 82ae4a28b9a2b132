// The camera: one ray per pixel, reported exactly (ideal) or through the
// structured-light sensor model.
#include "ray_camera.h"

#include <cmath>
#include <limits>
#include <vector>

#include "structured_light_camera.h"

namespace relmap::sim {

namespace {

dGeomID NewRay() {
  const dGeomID ray = dCreateRay(nullptr, 1.0);
  dGeomRaySetFirstContact(ray, 0);
  dGeomRaySetClosestHit(ray, 1);  // the nearest hit on each geom (meshes)
  dGeomRaySetBackfaceCull(ray, 0);
  return ray;
}

}  // namespace

RayCamera::RayCamera() {
  EnsureOdeReady();
  ray_ = NewRay();
  second_ray_ = NewRay();
}

RayCamera::~RayCamera() {
  dGeomDestroy(second_ray_);
  dGeomDestroy(ray_);
}

std::optional<RayHit> RayCamera::Cast(OdeWorld& world, const Eigen::Vector3d& origin,
                                      const Eigen::Vector3d& direction, double length,
                                      bool static_only) {
  std::vector<Entry> entries;
  return Nearest(ray_, CandidatesOf(world, static_only), origin, direction, length, entries);
}

CameraFrame RayCamera::Render(const CameraModel& camera, const LightSettings& light,
                              OdeWorld& world, SeededRandom& noise) {
  if (camera.sensor == Sensor::kKinectV1) {
    return RenderStructuredLight(camera, light, world, {ray_, second_ray_}, noise);
  }
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
      frame.body_ids[index] = TagOf(hit->geom).body_id;

      const Eigen::Vector3d hit_world = origin + hit->distance * ray_world;
      const Eigen::Vector3d rgb = ShadedColour(*hit, hit_world, light);
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
