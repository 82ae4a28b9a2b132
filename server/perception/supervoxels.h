// VCCS supervoxels of a cloud (docs/method.md §1) as plain data: what the features, the maps
// and the change detector need, without PCL types.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"

namespace relmap::perception {

// One VCCS voxel: the mean of the points in an 8 mm cell, and the normal VCCS computed
// for it (from the voxel and its two rings of adjacent voxels, oriented to the camera).
struct Voxel {
  Eigen::Vector3f position;
  Eigen::Vector3f normal;
  std::array<std::uint8_t, 3> rgb;
};

struct Supervoxel {
  // Position in Segmentation::supervoxels, also the row of the frame's feature matrix.
  // Ids are per frame (§1) and follow VCCS's label order, so they are deterministic.
  std::uint32_t id = 0;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();
  std::array<std::uint8_t, 3> rgb{};
  std::vector<Voxel> voxels;
  // Indices into the input cloud of the points that fall in this supervoxel.
  std::vector<std::int32_t> point_indices;
  // Ids of the adjacent supervoxels (VCCS adjacency, dropped supervoxels removed), sorted.
  std::vector<std::uint32_t> neighbours;
};

struct Segmentation {
  std::vector<Supervoxel> supervoxels;
  // Per point of the input cloud: the id of its supervoxel, or -1 for holes, points outside
  // the crop box and points of dropped supervoxels.
  std::vector<std::int32_t> point_labels;
  // Points that reached VCCS (finite and inside the crop box).
  std::size_t points_used = 0;
  // Stage times in milliseconds (filter/crop; VCCS including its voxel normals; the copy of
  // the voxel normals and the rest of the output).
  double filter_ms = 0, supervoxels_ms = 0, normals_ms = 0;
};

// Crops, runs VCCS with `config` and converts its output. Deterministic: the same cloud and
// config give the same segmentation. Errors: no point left after the crop; PCL failures.
StatusOr<Segmentation> ExtractSupervoxels(const Cloud& cloud, const SupervoxelConfig& config);

}  // namespace relmap::perception
