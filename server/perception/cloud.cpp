// Cloud: plain points to a validated PCL cloud and back.
#include "perception/cloud.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>
#include <string>

namespace relmap::perception {

Cloud::Cloud() : pcl_(std::make_shared<const PclCloud>()) {}

CloudPoint Cloud::point(std::size_t i) const {
  const pcl::PointXYZRGBA& p = (*pcl_)[i];
  return {p.x, p.y, p.z, p.r, p.g, p.b, p.a};
}

std::vector<CloudPoint> Cloud::points() const {
  std::vector<CloudPoint> out;
  out.reserve(size());
  for (std::size_t i = 0; i < size(); ++i) out.push_back(point(i));
  return out;
}

StatusOr<std::uint64_t> DeclaredPoints(std::uint32_t width, std::uint32_t height,
                                       const DecodeLimits& limits) {
  if (width == 0 || height == 0) {
    return InvalidArgumentError("cloud has width " + std::to_string(width) + " and height " +
                                std::to_string(height) + ": both must be > 0");
  }
  const std::uint64_t count = static_cast<std::uint64_t>(width) * height;
  if (count > static_cast<std::uint64_t>(limits.max_points)) {
    return ResourceExhaustedError("cloud has " + std::to_string(count) + " points, more than the " +
                                  std::to_string(limits.max_points) + " allowed");
  }
  return count;
}

StatusOr<Cloud> MakeCloud(std::uint32_t width, std::uint32_t height, std::vector<CloudPoint> points,
                          const DecodeLimits& limits) {
  const StatusOr<std::uint64_t> count = DeclaredPoints(width, height, limits);
  if (!count.ok()) return count.status();
  if (points.size() != *count) {
    return InvalidArgumentError("cloud declares " + std::to_string(width) + "x" +
                                std::to_string(height) + " points but holds " +
                                std::to_string(points.size()));
  }
  auto cloud = std::make_shared<PclCloud>();
  cloud->resize(points.size());
  cloud->width = width;
  cloud->height = height;
  std::size_t valid = 0;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CloudPoint& in = points[i];
    pcl::PointXYZRGBA& out = (*cloud)[i];
    out.r = in.r;
    out.g = in.g;
    out.b = in.b;
    out.a = in.a;
    if (!std::isfinite(in.x) || !std::isfinite(in.y) || !std::isfinite(in.z)) {
      out.x = out.y = out.z = nan;  // a hole, whatever the sensor wrote (NaN or ±Inf)
      continue;
    }
    const float m = limits.max_abs_coordinate;
    if (std::fabs(in.x) > m || std::fabs(in.y) > m || std::fabs(in.z) > m) {
      return InvalidArgumentError("point " + std::to_string(i) + " lies at (" +
                                  std::to_string(in.x) + ", " + std::to_string(in.y) + ", " +
                                  std::to_string(in.z) + "), beyond the " + std::to_string(m) +
                                  " m coordinate limit");
    }
    out.x = in.x;
    out.y = in.y;
    out.z = in.z;
    ++valid;
  }
  cloud->is_dense = valid == points.size();
  if (valid == 0) return InvalidArgumentError("cloud has no valid (finite) point");
  Cloud result;
  result.pcl_ = std::move(cloud);
  result.width_ = width;
  result.height_ = height;
  result.valid_points_ = valid;
  return result;
}

}  // namespace relmap::perception
