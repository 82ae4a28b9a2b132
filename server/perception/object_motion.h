// Where a push took the part of an object that moved (docs/method.md §5.1): the rigid
// motion that carries its before-points onto the after frame's surface, by point-to-plane
// ICP. The change detector asks it whether a target whose own points stayed went with its
// object.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "perception/camera_motion.h"

namespace relmap::perception {

// A point of the after frame's surface and its unit normal.
struct SurfacePoint {
  Eigen::Vector3f position;
  Eigen::Vector3f normal;
};

// The points of `seen` (a width x height frame, camera_motion.h) inside [lo, hi] on every
// `step`-th row and column, with their normals from neighbours 2 pixels away each side;
// points at holes, borders and depth jumps wider than `max_gap` have none and are left out.
std::vector<SurfacePoint> SurfaceWithin(const std::vector<SeenPoint>& seen, std::uint32_t width,
                                        std::uint32_t height, std::uint32_t step,
                                        const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
                                        float max_gap);

struct ObjectMotion {
  // Maps a before-point of the moved part to where it is in the after frame.
  Eigen::Isometry3f after_from_before = Eigen::Isometry3f::Identity();
  // The share of the part's points within `tolerance` of an after-point once moved.
  double inlier_share = 0;
};

// ICP of `part` onto `after` (both in the before frame's coordinates), from the identity,
// each point paired with its nearest after-point and drawn to that point's tangent plane
// (Chen and Medioni 1992: a face slid along itself converges in a few steps, where pairing
// points with points creeps): pairs up to `reach` apart first (the largest displacement
// looked for), then up to `tolerance` (the camera's noise). nullopt when fewer than half the
// part pairs up, or lies within `tolerance` of the after frame at the end: the part's
// motion is not rigid, or larger than `reach`, or the after frame does not show it.
std::optional<ObjectMotion> FitObjectMotion(const std::vector<Eigen::Vector3f>& part,
                                            const std::vector<SurfacePoint>& after, float reach,
                                            float tolerance);

}  // namespace relmap::perception
