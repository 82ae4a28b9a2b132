// One Gauss-Newton step of point-to-plane ICP (Chen and Medioni 1992), linearised in a small
// rotation: the normal equations of the pairs added, and the rigid increment they solve for.
// Shared by the camera's registration (camera_motion.cpp) and the object's (object_motion.cpp).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>

namespace relmap::perception {

class PointToPlaneStep {
 public:
  // A point where the current estimate puts it, paired with a point on a plane of unit
  // normal `normal`; `weight` scales its pull (a robust weight, 1 for none).
  void Add(const Eigen::Vector3f& moved, const Eigen::Vector3f& on_plane,
           const Eigen::Vector3f& normal, double weight = 1.0) {
    const double residual = normal.dot(moved - on_plane);
    Eigen::Matrix<double, 6, 1> jacobian;
    jacobian << moved.cross(normal).cast<double>(), normal.cast<double>();
    normal_matrix_ += weight * jacobian * jacobian.transpose();
    rhs_ -= weight * jacobian * residual;
    ++pairs_;
  }

  std::size_t pairs() const { return pairs_; }

  struct Increment {
    Eigen::Isometry3f motion;  // to apply before the current estimate: increment * estimate
    double rotation_rad;
    double translation_m;
  };

  // The increment that minimises the pairs' squared distances to their planes; `damping`
  // (Levenberg, in units of the normal matrix's mean diagonal) keeps a motion the planes
  // leave free at zero. nullopt when the solution is not finite.
  std::optional<Increment> Solve(double damping = 0.0) const {
    Eigen::Matrix<double, 6, 6> damped = normal_matrix_;
    damped.diagonal().array() += damping * normal_matrix_.diagonal().mean();
    const Eigen::Matrix<double, 6, 1> step = damped.ldlt().solve(rhs_);
    if (!step.allFinite()) return std::nullopt;
    const Eigen::Vector3d omega = step.head<3>();
    Increment increment{Eigen::Isometry3f::Identity(), omega.norm(), step.tail<3>().norm()};
    if (omega.norm() > 0) {
      increment.motion.linear() =
          Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix().cast<float>();
    }
    increment.motion.translation() = step.tail<3>().cast<float>();
    return increment;
  }

 private:
  Eigen::Matrix<double, 6, 6> normal_matrix_ = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs_ = Eigen::Matrix<double, 6, 1>::Zero();
  std::size_t pairs_ = 0;
};

}  // namespace relmap::perception
