// A cloud kept for later in a few hundred KB instead of the decoded ~10 MB (a PCL point is
// 32 bytes): the x, y, z of the finite points exactly, bit for bit, and their colour only
// when asked for. Depth cameras make the coordinates predictable: z changes little from
// one pixel to the next, and x, y follow from z and the pixel through the camera's
// intrinsics, so what is stored is the difference of the bits to that prediction, packed
// (word_planes.h). 255-260 KB for a Kinect frame of shared/data/real, 660 KB for the
// stereo table_scene_mug.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "common/status.h"
#include "perception/camera_motion.h"
#include "perception/cloud.h"

namespace relmap::perception {

class CompactCloud {
 public:
  CompactCloud() = default;
  // `cloud` with the colours of its finite points when `keep_colour`.
  static CompactCloud Of(const Cloud& cloud, bool keep_colour);

  // The cloud again: the same size, the same holes, every finite point's x, y, z bit
  // for bit, and its r, g, b if they were kept (else 0); holes have colour 0, every
  // point alpha 255. DATA_LOSS if the packed bytes are damaged.
  StatusOr<Cloud> Expand() const;

  bool has_colour() const { return has_colour_; }
  // The heap bytes held.
  std::size_t bytes() const;

 private:
  std::uint32_t width_ = 0;
  std::uint32_t height_ = 0;
  std::size_t finite_ = 0;
  bool has_colour_ = false;
  // The prediction of x and y from z; none for a cloud without a pinhole camera's pixel
  // grid, whose x and y are predicted by the previous finite point.
  std::optional<Intrinsics> intrinsics_;
  std::string holes_;    // one bit per point, set for a finite one
  std::string xyz_;      // per finite point, zigzagged bit differences: x, y, then z
  std::string colours_;  // per finite point, r g b, when kept
};

}  // namespace relmap::perception
