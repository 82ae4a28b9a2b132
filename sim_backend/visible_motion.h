// A body's motion as a camera can see it: the turns its shape and colour hide taken out.
// A plain ball turned about its centre, or a plain cylinder or capsule turned about its
// axis, covers the same space and shows the same colours as before; no sensor can tell
// the turn, so the simulator's truth of a push (ground_truth.h) does not count it as a
// displacement. A textured body (wood grain, checker) or any other shape shows its turns.
#pragma once

#include <Eigen/Geometry>

namespace relmap::sim {

// The rotations under which a body looks the same, in the world frame before the push.
struct ShapeSymmetry {
  enum class Kind {
    kNone,        // every turn shows
    kAboutPoint,  // a plain sphere: any turn about `centre`
    kAboutAxis,   // a plain cylinder or capsule: turns about the line `centre` + t `axis`
  };
  Kind kind = Kind::kNone;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit
};

// `motion` (a point p before the push is at motion * p after it) less the turn `symmetry`
// hides. About a point: the centre's translation alone. About an axis: the rotation's
// twist about the axis (its swing-twist decomposition, rotation = swing * twist) removed,
// so the axis goes where `motion` takes it and the body does not spin about it.
Eigen::Isometry3d VisibleMotion(const Eigen::Isometry3d& motion, const ShapeSymmetry& symmetry);

}  // namespace relmap::sim
