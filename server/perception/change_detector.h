// Labelling a push from two clouds (docs/method.md §5): did the target move?
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"
#include "perception/supervoxels.h"

namespace relmap::perception {

// The label and what it rests on.
struct ChangeEvidence {
  bool moved = false;
  ChangeMethod method = ChangeMethod::kVisibility;

  // kVisibility: the target's finite before-points, and how many of them the after frame
  // shows still there, seen through (vacated) or hidden behind something nearer (occluded);
  // the rest fall on holes of the after frame and say nothing.
  std::size_t target_points = 0;
  std::size_t supported_points = 0;
  std::size_t vacated_points = 0;
  std::size_t occluded_points = 0;
  // The same counts over the target's object (change_object.h), the target included: its
  // supervoxels and their finite points (counts of a large object are of an even sample,
  // scaled up). Without the frame's supervoxels the object is the
  // target alone.
  std::size_t object_supervoxels = 0;
  std::size_t object_points = 0;
  std::size_t object_supported_points = 0;
  std::size_t object_vacated_points = 0;
  std::size_t object_occluded_points = 0;
  // Of the vacated points (the target's; the object's), those with nothing within the
  // smallest motion that counts (ChangeDetectorConfig::min_motion) either.
  std::size_t vacated_beyond_motion_points = 0;
  std::size_t object_vacated_beyond_motion_points = 0;
  // When the object showed a move that the target's own points did not: the rigid motion
  // fitted to the object's supervoxels that moved (object_motion.h), if one fitted, and
  // what the after frame shows where it carries the target's points. A target shown there
  // worse than at its old place (fewer than half as many still there, or seen through at a
  // larger share, z >= 3) did not go with its object (a body flush against the pushed one),
  // and is not moved.
  bool object_motion_fitted = false;
  double object_motion_translation_m = 0;
  double object_motion_rotation_deg = 0;
  std::size_t carried_supported_points = 0;
  std::size_t carried_vacated_points = 0;
  std::size_t carried_occluded_points = 0;
  // When moved (kVisibility): the ids of the object's other supervoxels whose own points
  // show the move as the target's would (SeenCounts::Moved over their sampled points), in
  // id order. They moved, so they are moveable: the session learns them with the target
  // (docs/method.md §4.5).
  std::vector<std::uint32_t> moved_supervoxels;
  // The camera motion between the frames that was compensated first.
  double camera_rotation_deg = 0;
  double camera_translation_m = 0;

  // kPaper2018: before-cloud points in octree cells that are empty after the push, then
  // what is left after the statistical and the radius outlier removal, and the ICP.
  std::size_t difference_points = 0;
  std::size_t after_statistical = 0;
  std::size_t after_radius = 0;
  bool icp_ran = false;
  bool icp_converged = false;
  double icp_fitness = 0;  // m², mean squared nearest distance; meaningful if icp_ran

  double elapsed_ms = 0;
};

// `target` is a supervoxel of `before` (its points and voxels index and lie in `before`).
// Its object is the target alone.
StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const Supervoxel& target, const ChangeDetectorConfig& config);

// `object`: the other supervoxels of `before` on the target's object (change_object.h),
// which the visibility test judges beside the target (docs/method.md §5.1).
StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const Supervoxel& target,
                                      const std::vector<const Supervoxel*>& object,
                                      const ChangeDetectorConfig& config);

// The target is `frame[target_id]`, `frame` the supervoxels of `before`, and its object
// is found among them (ObjectOf, with config.object_smooth_angle_deg).
StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const std::vector<Supervoxel>& frame, std::uint32_t target_id,
                                      const ChangeDetectorConfig& config);

}  // namespace relmap::perception
