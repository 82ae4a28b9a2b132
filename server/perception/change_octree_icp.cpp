// The authors' labelling (docs/method.md §5) with PCL: octree difference (before-points
// where the after-cloud left empty cells), statistical then radius outlier removal on that
// small difference only, and ICP of the target's voxels onto what remains.
#include <pcl/filters/radius_outlier_removal.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/octree/octree_pointcloud_changedetector.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/icp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "perception/change_methods.h"

namespace relmap::perception {
namespace {

using XyzCloud = pcl::PointCloud<pcl::PointXYZ>;

// Step 1: the before-cloud points in cells that the after-cloud leaves empty (the space
// an object left). Indices are compared, not voxel centres: PCL rounds the centres.
std::uint64_t CellKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  // Coordinates are bounded by DecodeLimits (|v| <= 100 m): 21 bits per axis suffice.
  const auto wrap = [](std::int64_t v) {
    return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff;
  };
  return wrap(x) | (wrap(y) << 21) | (wrap(z) << 42);
}

// Keeps the difference points with no after-point within max(resolution, depth_noise * z²),
// looking at the cells of `resolution` around them (a cube of ±k cells).
XyzCloud::Ptr KeepVacated(const XyzCloud& difference, const Cloud& after, double resolution,
                          double depth_noise) {
  const double inverse = 1.0 / resolution;
  const auto cell = [inverse](float v) {
    return static_cast<std::int64_t>(std::floor(static_cast<double>(v) * inverse));
  };
  std::unordered_set<std::uint64_t> occupied;
  occupied.reserve(after.valid_points() / 4);
  for (const pcl::PointXYZRGBA& p : after.pcl()) {
    if (pcl::isFinite(p)) occupied.insert(CellKey(cell(p.x), cell(p.y), cell(p.z)));
  }
  XyzCloud::Ptr out(new XyzCloud);
  for (const pcl::PointXYZ& p : difference) {
    const double z = p.z;
    const double tolerance = std::max(resolution, depth_noise * z * z);
    const auto k = static_cast<std::int64_t>(std::min(8.0, std::ceil(tolerance * inverse)));
    const std::int64_t cx = cell(p.x), cy = cell(p.y), cz = cell(p.z);
    bool empty = true;
    for (std::int64_t dx = -k; dx <= k && empty; ++dx) {
      for (std::int64_t dy = -k; dy <= k && empty; ++dy) {
        for (std::int64_t dz = -k; dz <= k && empty; ++dz) {
          empty = !occupied.contains(CellKey(cx + dx, cy + dy, cz + dz));
        }
      }
    }
    if (empty) out->push_back(p);
  }
  return out;
}

XyzCloud::Ptr Difference(const Cloud& before, const Cloud& after, double resolution,
                         int min_points) {
  pcl::octree::OctreePointCloudChangeDetector<pcl::PointXYZRGBA> octree(resolution);
  octree.setInputCloud(after.pcl_ptr());
  octree.addPointsFromInputCloud();
  octree.switchBuffers();
  octree.setInputCloud(before.pcl_ptr());
  octree.addPointsFromInputCloud();
  pcl::Indices indices;
  octree.getPointIndicesFromNewVoxels(indices, min_points);
  XyzCloud::Ptr out(new XyzCloud);
  out->reserve(indices.size());
  for (const pcl::index_t i : indices) {
    const pcl::PointXYZRGBA& p = before.pcl()[static_cast<std::size_t>(i)];
    out->push_back(pcl::PointXYZ(p.x, p.y, p.z));
  }
  return out;
}

}  // namespace

void DetectByOctreeIcp(const Cloud& before, const Cloud& after, const Supervoxel& target,
                       const ChangeDetectorConfig& config, ChangeEvidence& e) {
  XyzCloud::Ptr difference =
      Difference(before, after, config.octree_resolution, config.min_points_per_cell);
  if (config.depth_noise > 0) {
    difference = KeepVacated(*difference, after, config.octree_resolution, config.depth_noise);
  }
  e.difference_points = difference->size();
  if (difference->empty()) return;  // step 2: empty -> not moved
  XyzCloud::Ptr statistical(new XyzCloud);
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> sor;
  sor.setInputCloud(difference);
  sor.setMeanK(config.sor_mean_k);
  sor.setStddevMulThresh(config.sor_stddev_mul);
  sor.filter(*statistical);
  e.after_statistical = statistical->size();
  XyzCloud::Ptr cleaned(new XyzCloud);
  if (!statistical->empty()) {
    pcl::RadiusOutlierRemoval<pcl::PointXYZ> ror;
    ror.setInputCloud(statistical);
    ror.setRadiusSearch(config.ror_radius);
    ror.setMinNeighborsInRadius(config.ror_min_neighbours);
    ror.filter(*cleaned);
  }
  e.after_radius = cleaned->size();
  if (cleaned->empty()) return;  // step 4: empty -> not moved
  XyzCloud::Ptr source(new XyzCloud);
  for (const Voxel& v : target.voxels) {
    source->push_back({v.position.x(), v.position.y(), v.position.z()});
  }
  pcl::IterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> icp;
  icp.setInputSource(source);
  icp.setInputTarget(cleaned);
  icp.setMaximumIterations(config.icp_max_iterations);
  icp.setMaxCorrespondenceDistance(config.icp_max_correspondence);
  XyzCloud aligned;
  icp.align(aligned);  // PCL prints a warning when no correspondence is found
  e.icp_ran = true;
  e.icp_converged = icp.hasConverged();
  e.icp_fitness = icp.getFitnessScore();
  // Step 6: moved iff ICP converged with a mean squared distance below the bound.
  e.moved = e.icp_converged && e.icp_fitness < config.max_fitness;
}

}  // namespace relmap::perception
