// Conversions between ODE's rotation matrices (3x4, row-major) and poses, and
// Eigen's.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>

namespace relmap::sim {

inline void ToOde(const Eigen::Matrix3d& r, dMatrix3 out) {
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) out[row * 4 + col] = r(row, col);
    out[row * 4 + 3] = 0;
  }
}

inline Eigen::Matrix3d FromOde(const dReal* r) {
  Eigen::Matrix3d m;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) m(row, col) = r[row * 4 + col];
  }
  return m;
}

// A pose from ODE's position (3) and rotation (3x4) arrays.
inline Eigen::Isometry3d ToPose(const dReal* position, const dReal* rotation) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = FromOde(rotation);
  t.translation() = Eigen::Vector3d(position[0], position[1], position[2]);
  return t;
}

inline Eigen::Isometry3d PoseOf(dBodyID body) {
  return ToPose(dBodyGetPosition(body), dBodyGetRotation(body));
}

inline Eigen::Isometry3d PoseOf(dGeomID geom) {
  return ToPose(dGeomGetPosition(geom), dGeomGetRotation(geom));
}

// Places `body` at `pose` at rest.
inline void SetPoseAtRest(dBodyID body, const Eigen::Isometry3d& pose) {
  dMatrix3 r;
  ToOde(pose.linear(), r);
  dBodySetPosition(body, pose.translation().x(), pose.translation().y(), pose.translation().z());
  dBodySetRotation(body, r);
  dBodySetLinearVel(body, 0, 0, 0);
  dBodySetAngularVel(body, 0, 0, 0);
  dBodySetForce(body, 0, 0, 0);
  dBodySetTorque(body, 0, 0, 0);
}

}  // namespace relmap::sim
