// VCCS supervoxels (docs/method.md §1): crop, optional pre-voxelisation, PCL
// SupervoxelClustering, then a plain-data copy with the small supervoxels dropped.
#include "perception/supervoxels.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <unordered_map>

#include "perception/grid_cell.h"

namespace relmap::perception {
namespace {

using Clock = std::chrono::steady_clock;
double MsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool InCrop(const pcl::PointXYZRGBA& p, const CropBox& c) {
  return !c.enabled || (p.x >= c.min_x && p.x <= c.max_x && p.y >= c.min_y && p.y <= c.max_y &&
                        p.z >= c.min_z && p.z <= c.max_z);
}

// The points VCCS sees, and for each input point the index of the VCCS input point that
// stands for it (-1: hole or cropped).
struct VccsInput {
  PclCloud::Ptr cloud{new PclCloud};
  std::vector<std::int32_t> source_of_input;
};

VccsInput SelectPoints(const PclCloud& input, const CropBox& crop) {
  VccsInput out;
  out.source_of_input.assign(input.size(), -1);
  out.cloud->reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    const pcl::PointXYZRGBA& p = input[i];
    if (!pcl::isFinite(p) || !InCrop(p, crop)) continue;
    out.source_of_input[i] = static_cast<std::int32_t>(out.cloud->size());
    out.cloud->push_back(p);
  }
  return out;
}

// Averages the selected points on a grid of `resolution` anchored at the origin: one point
// (mean position and colour) per occupied cell, in order of first appearance so that the
// result is deterministic. VCCS averages on its own grid of the same size afterwards.
VccsInput Prevoxelise(const PclCloud& input, const CropBox& crop, float resolution) {
  struct Sum {
    double x = 0, y = 0, z = 0, r = 0, g = 0, b = 0, a = 0;
    int n = 0;
  };
  VccsInput out;
  out.source_of_input.assign(input.size(), -1);
  std::unordered_map<std::uint64_t, std::int32_t> cell_index;
  cell_index.reserve(input.size() / 8);
  std::vector<Sum> sums;
  const float inv = 1.0f / resolution;
  for (std::size_t i = 0; i < input.size(); ++i) {
    const pcl::PointXYZRGBA& p = input[i];
    if (!pcl::isFinite(p) || !InCrop(p, crop)) continue;
    const std::uint64_t key = GridCellKey(p.x, p.y, p.z, inv);
    auto [it, inserted] = cell_index.try_emplace(key, static_cast<std::int32_t>(sums.size()));
    if (inserted) sums.emplace_back();
    Sum& s = sums[static_cast<std::size_t>(it->second)];
    s.x += p.x, s.y += p.y, s.z += p.z, s.r += p.r, s.g += p.g, s.b += p.b, s.a += p.a;
    ++s.n;
    out.source_of_input[i] = it->second;
  }
  out.cloud->resize(sums.size());
  for (std::size_t v = 0; v < sums.size(); ++v) {
    const Sum& s = sums[v];
    pcl::PointXYZRGBA& p = (*out.cloud)[v];
    const double n = s.n;
    p.x = static_cast<float>(s.x / n), p.y = static_cast<float>(s.y / n);
    p.z = static_cast<float>(s.z / n);
    p.r = static_cast<std::uint8_t>(std::lround(s.r / n));
    p.g = static_cast<std::uint8_t>(std::lround(s.g / n));
    p.b = static_cast<std::uint8_t>(std::lround(s.b / n));
    p.a = static_cast<std::uint8_t>(std::lround(s.a / n));
  }
  return out;
}

Eigen::Vector3f ToVector(float x, float y, float z) { return {x, y, z}; }

}  // namespace

StatusOr<Segmentation> ExtractSupervoxels(const Cloud& cloud, const SupervoxelConfig& config) {
  Segmentation seg;
  Clock::time_point start = Clock::now();
  VccsInput vccs_input = config.prevoxelise
                             ? Prevoxelise(cloud.pcl(), config.crop, config.voxel_resolution)
                             : SelectPoints(cloud.pcl(), config.crop);
  seg.points_used = 0;
  for (std::int32_t s : vccs_input.source_of_input) seg.points_used += s >= 0 ? 1 : 0;
  if (vccs_input.cloud->empty()) {
    return InvalidArgumentError(config.crop.enabled
                                    ? "no valid point of the cloud lies inside the workspace box"
                                    : "cloud has no valid (finite) point");
  }
  seg.filter_ms = MsSince(start);

  start = Clock::now();
  std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZRGBA>::Ptr> clusters;
  std::multimap<std::uint32_t, std::uint32_t> adjacency;
  pcl::PointCloud<pcl::PointXYZL>::Ptr labelled;
  try {
    pcl::SupervoxelClustering<pcl::PointXYZRGBA> vccs(config.voxel_resolution,
                                                      config.seed_resolution);
    // Set explicitly: PCL turns the transform on by default for organized clouds.
    vccs.setUseSingleCameraTransform(config.single_camera_transform);
    vccs.setColorImportance(config.colour_importance);
    vccs.setSpatialImportance(config.spatial_importance);
    vccs.setNormalImportance(config.normal_importance);
    vccs.setInputCloud(vccs_input.cloud);
    vccs.extract(clusters);
    vccs.getSupervoxelAdjacency(adjacency);
    labelled = vccs.getLabeledCloud();
  } catch (const std::exception& e) {
    return InternalError(std::string("VCCS supervoxel clustering failed: ") + e.what());
  }
  seg.supervoxels_ms = MsSince(start);

  start = Clock::now();
  // std::map iterates labels in increasing order: ids are deterministic.
  std::unordered_map<std::uint32_t, std::uint32_t> id_of_label;
  for (const auto& [label, sv] : clusters) {
    if (static_cast<int>(sv->voxels_->size()) < config.min_voxels) continue;
    const auto id = static_cast<std::uint32_t>(seg.supervoxels.size());
    id_of_label[label] = id;
    Supervoxel out;
    out.id = id;
    out.centroid = ToVector(sv->centroid_.x, sv->centroid_.y, sv->centroid_.z);
    out.normal = ToVector(sv->normal_.normal_x, sv->normal_.normal_y, sv->normal_.normal_z);
    out.rgb = {sv->centroid_.r, sv->centroid_.g, sv->centroid_.b};
    out.voxels.reserve(sv->voxels_->size());
    for (std::size_t v = 0; v < sv->voxels_->size(); ++v) {
      const pcl::PointXYZRGBA& p = (*sv->voxels_)[v];
      const pcl::Normal& n = (*sv->normals_)[v];
      out.voxels.push_back(
          {ToVector(p.x, p.y, p.z), ToVector(n.normal_x, n.normal_y, n.normal_z), {p.r, p.g, p.b}});
    }
    seg.supervoxels.push_back(std::move(out));
  }
  for (const auto& [a, b] : adjacency) {
    auto ia = id_of_label.find(a), ib = id_of_label.find(b);
    if (ia == id_of_label.end() || ib == id_of_label.end() || a == b) continue;
    seg.supervoxels[ia->second].neighbours.push_back(ib->second);
  }
  for (Supervoxel& sv : seg.supervoxels) {
    std::sort(sv.neighbours.begin(), sv.neighbours.end());
    sv.neighbours.erase(std::unique(sv.neighbours.begin(), sv.neighbours.end()),
                        sv.neighbours.end());
  }
  seg.point_labels.assign(cloud.size(), -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::int32_t source = vccs_input.source_of_input[i];
    if (source < 0) continue;
    const std::uint32_t label = (*labelled)[static_cast<std::size_t>(source)].label;
    auto it = id_of_label.find(label);
    if (it == id_of_label.end()) continue;
    seg.point_labels[i] = static_cast<std::int32_t>(it->second);
    seg.supervoxels[it->second].point_indices.push_back(static_cast<std::int32_t>(i));
  }
  seg.normals_ms = MsSince(start);
  return seg;
}

}  // namespace relmap::perception
