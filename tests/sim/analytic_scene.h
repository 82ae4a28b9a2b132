// A test double of the simulated world: a flat table facing the camera 1 m away and a
// few spheres and boxes lying on it, ray-cast analytically (no ODE). Two spheres and a
// box are moveable, one box is fixed. Respawn scatters the moveable ones
// deterministically; Push moves the moveable one the target lies on.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "simulated_scene.h"

namespace relmap::sim::testing {

class AnalyticScene : public SimulatedScene {
 public:
  // Body ids, as CameraFrame::body_ids reports them.
  static constexpr std::int32_t kTable = 0;
  static constexpr std::int32_t kBlueBall = 1;
  static constexpr std::int32_t kGreenBall = 2;
  static constexpr std::int32_t kYellowBrick = 3;
  static constexpr std::int32_t kFixedRedBlock = 4;
  // The table's surface, metres in front of the camera.
  static constexpr float kTableDepth = 1.0f;
  // A push moves its body this far across the table.
  static constexpr float kPushDistance = 0.1f;

  // A pinhole camera at the origin looking along +z (focal length 525 px at 640 px
  // across), the objects spawned from `seed`.
  explicit AnalyticScene(std::uint64_t seed, std::uint32_t width = 160, std::uint32_t height = 120);

  const std::string& name() const override { return name_; }
  CameraFrame Capture() override;
  bool IsMoveable(std::int32_t body_id) const override;
  void Respawn(std::uint64_t seed) override;
  PushReport Push(const Eigen::Vector3f& target, std::uint64_t seed) override;
  double motion_threshold() const override { return 0.01; }  // ODE scenes' default

  // The centre of body `id` (the table's is its surface's centre).
  Eigen::Vector3f centre(std::int32_t id) const {
    return bodies_[static_cast<std::size_t>(id)].centre;
  }
  // The ray through pixel (u, v), not normalised: z = 1.
  Eigen::Vector3f Ray(double u, double v) const;

 private:
  enum class Shape { kPlane, kSphere, kBox };
  struct Body {
    Shape shape;
    Eigen::Vector3f centre;
    // Sphere: radius in x. Box and the table's rectangle: half extents.
    Eigen::Vector3f size;
    std::array<std::uint8_t, 3> colour;
    bool moveable;
  };

  // The distance along `ray` to `body`'s surface, or +∞.
  static float Hit(const Body& body, const Eigen::Vector3f& ray);
  // The distance from `point` to `body`'s surface (0 inside).
  static float Distance(const Body& body, const Eigen::Vector3f& point);
  // Half the width of the body's footprint on the table, for spacing.
  static float Footprint(const Body& body);
  // Whether body `id` at its place stays on the table clear of the others.
  bool FitsAt(std::size_t id) const;

  std::string name_ = "AnalyticScene";
  std::uint32_t width_;
  std::uint32_t height_;
  float focal_;
  std::vector<Body> bodies_;
};

}  // namespace relmap::sim::testing
