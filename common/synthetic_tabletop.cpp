// Ray casting of the synthetic tabletop: table plane, three boxes and two spheres.
#include "common/synthetic_tabletop.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>

namespace relmap::synthetic {
namespace {

constexpr float kMaxRange = 3.0f;

struct Box {  // in table coordinates: x right, y away from the camera, z up
  Eigen::Vector3f centre, half;
  std::array<std::uint8_t, 3> rgb;
};
struct Sphere {
  Eigen::Vector3f centre;
  float radius;
  std::array<std::uint8_t, 3> rgb;
};

// Slab test; returns the entry distance along the ray or +inf.
float HitBox(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Box& b) {
  float t0 = 0, t1 = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    const float lo = b.centre[a] - b.half[a], hi = b.centre[a] + b.half[a];
    if (std::fabs(d[a]) < 1e-9f) {
      if (o[a] < lo || o[a] > hi) return std::numeric_limits<float>::infinity();
      continue;
    }
    float ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1 ? t0 : std::numeric_limits<float>::infinity();
}

float HitSphere(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Sphere& s) {
  const Eigen::Vector3f oc = o - s.centre;
  const float b = oc.dot(d), c = oc.squaredNorm() - s.radius * s.radius;
  const float disc = b * b - c * d.squaredNorm();
  if (disc < 0) return std::numeric_limits<float>::infinity();
  const float t = (-b - std::sqrt(disc)) / d.squaredNorm();
  return t > 0 ? t : std::numeric_limits<float>::infinity();
}

}  // namespace

Tabletop MakeTabletop(const TabletopOptions& options) {
  const std::vector<Box> boxes = {
      {{-0.20f, 0.05f, 0.05f}, {0.05f, 0.04f, 0.05f}, {200, 30, 30}},
      {{0.10f, 0.00f, 0.03f}, {0.06f, 0.06f, 0.03f}, {30, 160, 40}},
      {{0.00f, 0.25f, 0.08f}, {0.04f, 0.08f, 0.08f}, {40, 60, 210}},
  };
  const std::vector<Sphere> spheres = {
      {{0.25f, 0.20f, 0.05f}, 0.05f, {230, 210, 30}},
      {{-0.12f, -0.15f, 0.04f}, 0.04f, {200, 40, 200}},
  };
  // Camera frame: x right, y down, z forward. The table frame's origin is where the optical
  // axis meets the table.
  const float pitch = options.camera_pitch_deg * static_cast<float>(M_PI) / 180.0f;
  const Eigen::Vector3f up(0, -std::cos(pitch), -std::sin(pitch));
  const Eigen::Vector3f away = Eigen::Vector3f(0, 0, 1) - up * up.z();  // optical axis on table
  const Eigen::Vector3f forward = away.normalized();
  const Eigen::Vector3f right = forward.cross(up).normalized() * -1.0f;
  const Eigen::Vector3f origin = Eigen::Vector3f(0, 0, 1) * (options.camera_height / -up.z());
  Eigen::Matrix3f to_table;  // rows: table axes in camera coordinates
  to_table.row(0) = right;
  to_table.row(1) = forward;
  to_table.row(2) = up;

  const float f = 525.0f * static_cast<float>(options.width) / 640.0f;
  const float cx = (static_cast<float>(options.width) - 1) / 2;
  const float cy = (static_cast<float>(options.height) - 1) / 2;
  std::mt19937 rng(options.seed);
  std::normal_distribution<float> noise(0.0f, 1.0f);
  std::uniform_int_distribution<int> texture(-12, 12);

  Tabletop scene;
  scene.objects = static_cast<int>(boxes.size() + spheres.size());
  const std::size_t n = static_cast<std::size_t>(options.width) * options.height;
  std::vector<pcd::Point> points(n);
  scene.object_of_point.assign(n, -1);
  const Eigen::Vector3f camera_in_table = to_table * (-origin);
  for (std::uint32_t v = 0; v < options.height; ++v) {
    for (std::uint32_t u = 0; u < options.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * options.width + u;
      const Eigen::Vector3f ray((static_cast<float>(u) - cx) / f, (static_cast<float>(v) - cy) / f,
                                1.0f);  // z = 1: t is the depth
      const Eigen::Vector3f d = to_table * ray;
      float best = std::numeric_limits<float>::infinity();
      int object = -1;
      std::array<std::uint8_t, 3> rgb{};
      if (d.z() < 0) {  // the table plane z = 0
        best = -camera_in_table.z() / d.z();
        object = 0;
        const int t = texture(rng);
        rgb = {static_cast<std::uint8_t>(170 + t), static_cast<std::uint8_t>(140 + t),
               static_cast<std::uint8_t>(100 + t)};
      }
      for (std::size_t b = 0; b < boxes.size(); ++b) {
        const float t = HitBox(camera_in_table, d, boxes[b]);
        if (t < best) best = t, object = static_cast<int>(b) + 1, rgb = boxes[b].rgb;
      }
      for (std::size_t s = 0; s < spheres.size(); ++s) {
        const float t = HitSphere(camera_in_table, d, spheres[s]);
        if (t < best) {
          best = t, object = static_cast<int>(boxes.size() + s) + 1, rgb = spheres[s].rgb;
        }
      }
      pcd::Point& p = points[i];
      p.r = rgb[0], p.g = rgb[1], p.b = rgb[2];
      if (object < 0 || best > kMaxRange) {
        p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const float z = best * (1.0f + options.depth_noise * best * noise(rng));
      p.x = ray.x() * z, p.y = ray.y() * z, p.z = z;
      scene.object_of_point[i] = object;
    }
  }
  scene.width = options.width;
  scene.height = options.height;
  scene.points = std::move(points);
  return scene;
}

}  // namespace relmap::synthetic
