// A body's motion less the turns its symmetry hides (see visible_motion.h).
#include "visible_motion.h"

namespace relmap::sim {

Eigen::Isometry3d VisibleMotion(const Eigen::Isometry3d& motion, const ShapeSymmetry& symmetry) {
  if (symmetry.kind == ShapeSymmetry::Kind::kNone) return motion;
  const Eigen::Vector3d& c = symmetry.centre;
  Eigen::Matrix3d kept = Eigen::Matrix3d::Identity();  // the turn that shows
  if (symmetry.kind == ShapeSymmetry::Kind::kAboutAxis) {
    // rotation = swing * twist, the twist about the axis: the twist's quaternion is the
    // rotation's with its vector part projected on the axis (undefined, and the identity,
    // for a half turn about a line perpendicular to the axis).
    const Eigen::Quaterniond q(motion.linear());
    const Eigen::Vector3d along = q.vec().dot(symmetry.axis) * symmetry.axis;
    Eigen::Quaterniond twist(q.w(), along.x(), along.y(), along.z());
    if (twist.squaredNorm() < 1e-18) {
      twist = Eigen::Quaterniond::Identity();
    } else {
      twist.normalize();
    }
    kept = (q * twist.conjugate()).toRotationMatrix();
  }
  // p -> motion(c) + kept (p - c): the centre goes where the motion takes it.
  Eigen::Isometry3d visible = Eigen::Isometry3d::Identity();
  visible.linear() = kept;
  visible.translation() = motion * c - kept * c;
  return visible;
}

}  // namespace relmap::sim
