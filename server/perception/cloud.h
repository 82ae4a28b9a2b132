// A decoded, validated point cloud (x y z + RGBA, organized or not). The points live in a
// PCL cloud (decoded once, docs/architecture.md "one representation per stage"), but this header
// does not include PCL, so that later layers do not pay PCL's compile cost.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "common/pcd/point.h"
#include "common/status.h"
#include "perception/perception_config.h"

namespace pcl {
struct PointXYZRGBA;
template <typename PointT>
class PointCloud;
}  // namespace pcl

namespace relmap::perception {

using PclCloud = pcl::PointCloud<pcl::PointXYZRGBA>;

// One point as plain data. A hole of a depth camera has NaN x, y, z.
using CloudPoint = pcd::Point;

// Immutable and cheap to copy (the points are shared).
class Cloud {
 public:
  Cloud();

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  bool organized() const { return height_ > 1; }
  std::size_t size() const { return static_cast<std::size_t>(width_) * height_; }
  // Points with finite x, y, z.
  std::size_t valid_points() const { return valid_points_; }

  CloudPoint point(std::size_t i) const;
  std::vector<CloudPoint> points() const;

  // The PCL representation, for the PCL-using translation units of this layer.
  const PclCloud& pcl() const { return *pcl_; }
  const std::shared_ptr<const PclCloud>& pcl_ptr() const { return pcl_; }

 private:
  friend StatusOr<Cloud> MakeCloud(std::uint32_t, std::uint32_t, std::vector<CloudPoint>,
                                   const DecodeLimits&);
  std::shared_ptr<const PclCloud> pcl_;
  std::uint32_t width_ = 0;
  std::uint32_t height_ = 0;
  std::size_t valid_points_ = 0;
};

// width x height, the points a cloud declares: INVALID_ARGUMENT for an empty size,
// RESOURCE_EXHAUSTED beyond limits.max_points (a limit of the server, not a malformed
// cloud). Computed in 64 unsigned bits, where two 32-bit sizes cannot wrap.
StatusOr<std::uint64_t> DeclaredPoints(std::uint32_t width, std::uint32_t height,
                                       const DecodeLimits& limits);

// Builds a cloud from plain points (row-major for organized clouds). Points with any
// non-finite coordinate become holes (NaN); the check for absurd coordinates and the
// point limit of `limits` apply; a cloud with no finite point is an error.
StatusOr<Cloud> MakeCloud(std::uint32_t width, std::uint32_t height, std::vector<CloudPoint> points,
                          const DecodeLimits& limits = {});

}  // namespace relmap::perception
