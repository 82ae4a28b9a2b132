// Ray casting against a handful of analytic shapes: t along the ray d = (x', y', 1)
// of each pixel, the nearest positive t wins, and the point is t·d.
#include "sim/analytic_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "common/random.h"

namespace relmap::sim::testing {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Where the moveable objects spawn (x, y centre ranges, metres).
constexpr float kSpawnX = 0.35f, kSpawnY = 0.25f;
// Objects keep this much table between them.
constexpr float kClearance = 0.02f;
// A push reaches a body whose surface lies this close to the target point.
constexpr float kReach = 0.02f;

// A SplitMix64 stream: uniform numbers in [0, 1).
class Uniforms {
 public:
  explicit Uniforms(std::uint64_t seed) : state_(seed) {}
  float Next() { return static_cast<float>(UnitFromBits(SplitMix64Next(state_))); }
  float In(float low, float high) { return low + (high - low) * Next(); }

 private:
  std::uint64_t state_;
};

}  // namespace

AnalyticScene::AnalyticScene(std::uint64_t seed, std::uint32_t width, std::uint32_t height)
    : width_(width), height_(height), focal_(525.0f * static_cast<float>(width) / 640.0f) {
  const float table = kTableDepth;
  bodies_ = {
      {Shape::kPlane, {0, 0, table}, {0.5f, 0.35f, 0}, {160, 120, 80}, false},
      {Shape::kSphere, {0, 0, table - 0.06f}, {0.06f, 0, 0}, {40, 80, 220}, true},
      {Shape::kSphere, {0, 0, table - 0.05f}, {0.05f, 0, 0}, {40, 180, 60}, true},
      {Shape::kBox, {0, 0, table - 0.03f}, {0.05f, 0.035f, 0.03f}, {230, 200, 40}, true},
      {Shape::kBox, {0.12f, -0.12f, table - 0.04f}, {0.05f, 0.05f, 0.04f}, {200, 40, 40}, false},
  };
  Respawn(seed);
}

Eigen::Vector3f AnalyticScene::Ray(double u, double v) const {
  return {static_cast<float>((u - 0.5 * (width_ - 1)) / focal_),
          static_cast<float>((v - 0.5 * (height_ - 1)) / focal_), 1.0f};
}

float AnalyticScene::Hit(const Body& body, const Eigen::Vector3f& ray) {
  const Eigen::Vector3f& c = body.centre;
  switch (body.shape) {
    case Shape::kPlane: {
      const float t = c.z() / ray.z();
      const Eigen::Vector3f p = t * ray;
      return std::abs(p.x() - c.x()) <= body.size.x() && std::abs(p.y() - c.y()) <= body.size.y()
                 ? t
                 : kInfinity;
    }
    case Shape::kSphere: {
      // |t·d − c|² = r²: a t² − 2 b t + (|c|² − r²) = 0, the nearer root.
      const float a = ray.squaredNorm(), b = ray.dot(c);
      const float r = body.size.x();
      const float discriminant = b * b - a * (c.squaredNorm() - r * r);
      if (discriminant < 0) return kInfinity;
      const float t = (b - std::sqrt(discriminant)) / a;
      return t > 0 ? t : kInfinity;
    }
    case Shape::kBox: {
      // Slabs: the ray is inside the box between the last entry and the first exit.
      float enter = 0, leave = kInfinity;
      for (int axis = 0; axis < 3; ++axis) {
        const float low = c[axis] - body.size[axis], high = c[axis] + body.size[axis];
        if (ray[axis] == 0) {
          if (low > 0 || high < 0) return kInfinity;
          continue;
        }
        const float t0 = low / ray[axis], t1 = high / ray[axis];
        enter = std::max(enter, std::min(t0, t1));
        leave = std::min(leave, std::max(t0, t1));
      }
      return enter <= leave && enter > 0 ? enter : kInfinity;
    }
  }
  return kInfinity;
}

float AnalyticScene::Distance(const Body& body, const Eigen::Vector3f& point) {
  const Eigen::Vector3f offset = point - body.centre;
  if (body.shape == Shape::kSphere) return std::max(0.0f, offset.norm() - body.size.x());
  const Eigen::Vector3f outside = (offset.cwiseAbs() - body.size).cwiseMax(0.0f);
  return outside.norm();
}

float AnalyticScene::Footprint(const Body& body) {
  return body.shape == Shape::kSphere ? body.size.x() : body.size.head<2>().norm();
}

bool AnalyticScene::FitsAt(std::size_t id) const {
  const Body& body = bodies_[id];
  const Body& table = bodies_[kTable];
  const float reach = Footprint(body);
  if (std::abs(body.centre.x()) + reach > table.size.x() ||
      std::abs(body.centre.y()) + reach > table.size.y()) {
    return false;
  }
  for (std::size_t other = 1; other < bodies_.size(); ++other) {
    if (other == id) continue;
    const float apart = (bodies_[other].centre - body.centre).head<2>().norm();
    if (apart < reach + Footprint(bodies_[other]) + kClearance) return false;
  }
  return true;
}

CameraFrame AnalyticScene::Capture() {
  CameraFrame frame;
  frame.width = width_;
  frame.height = height_;
  frame.points.resize(static_cast<std::size_t>(width_) * height_);
  frame.body_ids.assign(frame.points.size(), kNoBody);
  for (std::uint32_t v = 0; v < height_; ++v) {
    for (std::uint32_t u = 0; u < width_; ++u) {
      const Eigen::Vector3f ray = Ray(u, v);
      float nearest = kInfinity;
      std::int32_t hit = kNoBody;
      for (std::size_t id = 0; id < bodies_.size(); ++id) {
        if (const float t = Hit(bodies_[id], ray); t < nearest) {
          nearest = t, hit = static_cast<std::int32_t>(id);
        }
      }
      const std::size_t i = static_cast<std::size_t>(v) * width_ + u;
      CameraPoint& point = frame.points[i];
      if (hit == kNoBody) {
        point.x = point.y = point.z = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const Eigen::Vector3f p = nearest * ray;
      point.x = p.x(), point.y = p.y(), point.z = p.z();
      auto colour = bodies_[static_cast<std::size_t>(hit)].colour;
      if (hit == kTable) {
        // Wood grain: a gentle wave of brightness across the table.
        const float grain = 1.0f + 0.08f * std::sin(60.0f * p.x() + 4.0f * std::sin(9.0f * p.y()));
        for (std::uint8_t& channel : colour) {
          channel = static_cast<std::uint8_t>(std::min(255.0f, channel * grain));
        }
      }
      point.r = colour[0], point.g = colour[1], point.b = colour[2];
      frame.body_ids[i] = hit;
    }
  }
  return frame;
}

bool AnalyticScene::IsMoveable(std::int32_t body_id) const {
  return body_id >= 0 && static_cast<std::size_t>(body_id) < bodies_.size() &&
         bodies_[static_cast<std::size_t>(body_id)].moveable;
}

void AnalyticScene::Respawn(std::uint64_t seed) {
  Uniforms random(seed);
  for (std::size_t id = 1; id < bodies_.size(); ++id) {
    if (!bodies_[id].moveable) continue;
    bodies_[id].centre.head<2>() = Eigen::Vector2f(100, 100);  // out of the others' way
  }
  for (std::size_t id = 1; id < bodies_.size(); ++id) {
    Body& body = bodies_[id];
    if (!body.moveable) continue;
    for (int attempt = 0; attempt < 1000; ++attempt) {
      body.centre.x() = random.In(-kSpawnX, kSpawnX);
      body.centre.y() = random.In(-kSpawnY, kSpawnY);
      if (FitsAt(id)) break;
    }
  }
}

PushReport AnalyticScene::Push(const Eigen::Vector3f& target, std::uint64_t seed) {
  PushReport report;
  report.executed = true;
  report.simulated_seconds = 1.0;
  report.motion_threshold = motion_threshold();
  report.body_motions.assign(bodies_.size(), Eigen::Isometry3f::Identity());
  std::size_t nearest = kTable;
  float distance = Distance(bodies_[kTable], target);
  for (std::size_t id = 1; id < bodies_.size(); ++id) {
    if (const float d = Distance(bodies_[id], target); d < distance) nearest = id, distance = d;
  }
  if (distance > kReach) return report;
  report.target_body = static_cast<std::int32_t>(nearest);
  Body& body = bodies_[nearest];
  if (!body.moveable) return report;
  // The push direction is drawn; a blocked one turns by 45° until one is free.
  const Eigen::Vector3f from = body.centre;
  const double angle = 2 * std::numbers::pi * Uniforms(seed).Next();
  for (int turn = 0; turn < 8; ++turn) {
    const double a = angle + turn * std::numbers::pi / 4;
    body.centre = from + kPushDistance * Eigen::Vector3f(static_cast<float>(std::cos(a)),
                                                         static_cast<float>(std::sin(a)), 0);
    if (FitsAt(nearest)) {
      report.moved_bodies.push_back(report.target_body);
      report.body_motions[nearest] = Eigen::Translation3f(body.centre - from);
      return report;
    }
  }
  body.centre = from;
  return report;
}

}  // namespace relmap::sim::testing
