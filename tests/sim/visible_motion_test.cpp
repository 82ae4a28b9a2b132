// The turns a body's symmetry hides, taken out of its motion: hand-computed cases.
#include "visible_motion.h"

#include <gtest/gtest.h>

#include <numbers>

namespace relmap::sim {
namespace {

using Eigen::AngleAxisd;
using Eigen::Isometry3d;
using Eigen::Vector3d;

constexpr double kQuarter = std::numbers::pi / 2;

// Turn by `angle` about the line through `centre` along `axis`, then translate by `shift`.
Isometry3d TurnThenShift(const Vector3d& centre, const Vector3d& axis, double angle,
                         const Vector3d& shift) {
  Isometry3d m = Isometry3d::Identity();
  m.linear() = AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  m.translation() = centre - m.linear() * centre + shift;
  return m;
}

ShapeSymmetry Sphere(const Vector3d& centre) {
  return {.kind = ShapeSymmetry::Kind::kAboutPoint, .centre = centre};
}

ShapeSymmetry Cylinder(const Vector3d& centre, const Vector3d& axis) {
  return {.kind = ShapeSymmetry::Kind::kAboutAxis, .centre = centre, .axis = axis.normalized()};
}

TEST(VisibleMotion, ABallTurnedAboutItsCentreStaysWhereItWas) {
  const Vector3d c(0.3, -0.1, 0.8);
  const Isometry3d spin = TurnThenShift(c, Vector3d(1, 2, 3), 1.2, Vector3d::Zero());
  const Vector3d on_surface = c + Vector3d(0, 0, 0.05);
  // The point itself moved by more than a scene's motion threshold (1 cm).
  EXPECT_GT((spin * on_surface - on_surface).norm(), 0.03);
  const Isometry3d seen = VisibleMotion(spin, Sphere(c));
  EXPECT_NEAR((seen * on_surface - on_surface).norm(), 0.0, 1e-12);
}

TEST(VisibleMotion, ABallThatRolledMovesEveryPointByItsCentresTranslation) {
  // Rolled 2 cm along x: a quarter turn about y and the shift; every point of the
  // ball, seen, moves by 2 cm.
  const Vector3d c(0, 0, 0.05);
  const Isometry3d rolled = TurnThenShift(c, Vector3d::UnitY(), kQuarter, Vector3d(0.02, 0, 0));
  const Isometry3d seen = VisibleMotion(rolled, Sphere(c));
  for (const Vector3d& p :
       {Vector3d(0, 0, 0.1), Vector3d(0.05, 0, 0.05), Vector3d(0, -0.05, 0.05)}) {
    EXPECT_NEAR((seen * p - p).norm(), 0.02, 1e-12);
    EXPECT_TRUE((seen * p - p).isApprox(Vector3d(0.02, 0, 0), 1e-12));
  }
}

TEST(VisibleMotion, ACylinderSpunAboutItsAxisStaysWhereItWas) {
  const Vector3d c(0.1, 0.2, 0.8), axis(0, 0, 1);
  const Isometry3d spin = TurnThenShift(c, axis, 2.0, Vector3d::Zero());
  const Vector3d on_side = c + Vector3d(0.04, 0, 0.03);
  const Isometry3d seen = VisibleMotion(spin, Cylinder(c, axis));
  EXPECT_NEAR((seen * on_side - on_side).norm(), 0.0, 1e-12);
}

TEST(VisibleMotion, ACylinderTippedOverKeepsTheTipButNotTheSpin) {
  // A can on its end (axis z) spun by 1 rad about z, then tipped a quarter turn about x
  // through its centre: seen, only the tip shows: the point on the axis's top goes to
  // where the tip takes it, and a point on its side moves as the tip alone moves it.
  const Vector3d c(0, 0, 0.06), z = Vector3d::UnitZ();
  Isometry3d tip = TurnThenShift(c, Vector3d::UnitX(), kQuarter, Vector3d::Zero());
  const Isometry3d spin = TurnThenShift(c, z, 1.0, Vector3d::Zero());
  const Isometry3d seen = VisibleMotion(tip * spin, Cylinder(c, z));
  EXPECT_TRUE(seen.isApprox(tip, 1e-12));
  const Vector3d top = c + Vector3d(0, 0, 0.06);
  EXPECT_TRUE((seen * top).isApprox(c + Vector3d(0, -0.06, 0), 1e-12));
}

TEST(VisibleMotion, WithoutASymmetryEveryTurnShows) {
  const Isometry3d m =
      TurnThenShift(Vector3d(1, 0, 0), Vector3d(0, 1, 1), 0.7, Vector3d(0, 0, 0.1));
  EXPECT_TRUE(VisibleMotion(m, ShapeSymmetry{}).isApprox(m, 1e-15));
}

TEST(VisibleMotion, AHalfTurnAcrossTheAxisIsKeptWhole) {
  // A half turn about x has no twist about z (its quaternion's vector part is along x):
  // the decomposition leaves it whole.
  const Vector3d c(0, 0, 0);
  const Isometry3d flip = TurnThenShift(c, Vector3d::UnitX(), std::numbers::pi, Vector3d::Zero());
  EXPECT_TRUE(VisibleMotion(flip, Cylinder(c, Vector3d::UnitZ())).isApprox(flip, 1e-12));
}

}  // namespace
}  // namespace relmap::sim
