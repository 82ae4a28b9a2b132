// Point-to-solid distances in the geom's frame, one small formula per shape.
#include "point_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ode_math.h"
#include "ode_world.h"

namespace relmap::sim {
namespace {

// Distance from p to the triangle (a, b, c): Ericson, Real-Time Collision
// Detection, 5.1.5 (closest point by Voronoi region).
double PointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                             const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denominator = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

double MeshDistance(const MeshData& mesh, const Eigen::Vector3d& p) {
  const auto vertex = [&](std::size_t i) {
    return Eigen::Vector3d(mesh.vertices[3 * i], mesh.vertices[3 * i + 1],
                           mesh.vertices[3 * i + 2]);
  };
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    best = std::min(best,
                    PointTriangleDistance(p, vertex(mesh.indices[t]), vertex(mesh.indices[t + 1]),
                                          vertex(mesh.indices[t + 2])));
  }
  return best;
}

}  // namespace

double DistanceToGeom(dGeomID geom, const Eigen::Vector3d& point) {
  const Eigen::Vector3d p = PoseOf(geom).inverse() * point;
  switch (dGeomGetClass(geom)) {
    case dBoxClass: {
      dVector3 lengths;
      dGeomBoxGetLengths(geom, lengths);
      const Eigen::Vector3d half(lengths[0] / 2, lengths[1] / 2, lengths[2] / 2);
      return (p.cwiseAbs() - half).cwiseMax(0.0).norm();
    }
    case dSphereClass:
      return std::max(0.0, p.norm() - dGeomSphereGetRadius(geom));
    case dCapsuleClass: {
      dReal radius = 0, length = 0;
      dGeomCapsuleGetParams(geom, &radius, &length);
      const Eigen::Vector3d on_axis(0, 0, std::clamp(p.z(), -length / 2, length / 2));
      return std::max(0.0, (p - on_axis).norm() - radius);
    }
    case dCylinderClass: {
      dReal radius = 0, length = 0;
      dGeomCylinderGetParams(geom, &radius, &length);
      const double radial = std::max(0.0, std::hypot(p.x(), p.y()) - radius);
      const double axial = std::max(0.0, std::abs(p.z()) - length / 2);
      return std::hypot(radial, axial);
    }
    case dTriMeshClass:
      return MeshDistance(*TagOf(geom).mesh, p);
    default:
      return std::numeric_limits<double>::infinity();
  }
}

}  // namespace relmap::sim
