// What the change detector needs of a frame, kept compact until an outcome comes with the
// cloud after the push (docs/method.md §5): the frame's cloud (compact_cloud.h), which
// supervoxel each of its points belongs to, the positions of every supervoxel's voxels, and
// which object each supervoxel is on (change_object.h).
// The features, normals and the rest of the segmentation are not kept. ~0.3-0.8 MB for a
// 640x480 frame, where the Frame itself holds ~12 MB.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"
#include "perception/compact_cloud.h"
#include "perception/frame.h"
#include "perception/perception_config.h"

namespace relmap::perception {

// The before cloud and a target as DetectChange reads them.
struct ChangeInput {
  Cloud before;
  // point_indices (ascending, as VCCS labelled them) and the voxels' positions; the
  // voxels' normals and colours are zero, and centroid, rgb, neighbours are not set.
  Supervoxel target;
  // The other supervoxels on the target's object (kVisibility only): id and point_indices.
  std::vector<Supervoxel> object;

  // `object` as DetectChange takes it.
  std::vector<const Supervoxel*> ObjectPointers() const;
};

class ChangeBefore {
 public:
  // Keeps the colours of `frame`'s cloud only if `config` reads them (kVisibility with
  // a colour_tolerance).
  static ChangeBefore Of(const Frame& frame, const ChangeDetectorConfig& config);

  std::size_t supervoxels() const { return voxel_offsets_.size() - 1; }

  // The before cloud and supervoxel `supervoxel_id`: DetectChange on them gives what it
  // gives on the frame's own. INVALID_ARGUMENT for an id the frame does not have;
  // DATA_LOSS if the packed bytes are damaged.
  StatusOr<ChangeInput> Expand(std::uint32_t supervoxel_id) const;

  // The heap bytes held.
  std::size_t bytes() const;

 private:
  CompactCloud cloud_;
  std::string point_labels_;  // per cloud point, its supervoxel id or -1 (packed)
  std::size_t points_ = 0;
  std::string voxel_positions_;  // x y z float bits of every voxel, supervoxel after supervoxel
  std::vector<std::uint32_t> voxel_offsets_{0};  // supervoxel i: [offsets[i], offsets[i+1])
  std::vector<std::uint32_t> object_labels_;     // per supervoxel (ObjectLabels); kVisibility
};

}  // namespace relmap::perception
