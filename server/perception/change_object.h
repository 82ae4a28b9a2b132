// The object a pushed supervoxel belongs to (docs/method.md §5.1, "Object evidence"): the
// supervoxels reached from it through locally convex or smooth connections (Stein et al.
// 2014, "Object Partitioning using Local Convexity", LCCP). A push moves a rigid object, not
// a supervoxel: a brick slid along its own top leaves its top's pixels on the same surface,
// but its trailing faces are vacated, and they belong to the same convex object.
#pragma once

#include <cstdint>
#include <vector>

#include "perception/supervoxels.h"

namespace relmap::perception {

// Whether two adjacent supervoxels lie on one object: their connection is convex (Stein et
// al. 2014, eq. 3: with d = (x_a - x_b) / |x_a - x_b|, n_a . d > n_b . d), or their normals
// are less than `smooth_angle_deg` apart (eq. 4, the concavity tolerance: a flat surface's
// noisy normals make every connection look slightly concave or convex). A concave crease (a
// brick standing on a table) separates objects.
bool OnOneObject(const Supervoxel& a, const Supervoxel& b, double smooth_angle_deg);

// Per supervoxel of `frame`, its object: the supervoxels connected to it through
// OnOneObject share a label (0, 1, ... in the order of their lowest id). OnOneObject is
// symmetric, so an object is the same whichever of its supervoxels it is grown from.
// `frame[i].id == i` and `neighbours` index it (ids beyond the frame are ignored).
std::vector<std::uint32_t> ObjectLabels(const std::vector<Supervoxel>& frame,
                                        double smooth_angle_deg);

// The ids of the supervoxels on the object of `target_id`: the target first, then the
// others in id order; empty for an id the frame does not have.
std::vector<std::uint32_t> ObjectOf(const std::vector<Supervoxel>& frame, std::uint32_t target_id,
                                    double smooth_angle_deg);

}  // namespace relmap::perception
