// The paper's FPFH "on the raw points": per supervoxel, PointFpfh at the raw input points of
// the supervoxel ∪ its neighbours, that union as search surface, averaged over the union.
// The voxel schemes evaluate FPFH at 8 mm voxel means, which removes the sensor noise that
// spreads the raw-point histograms (docs/features.md).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_set>

#include "perception/fpfh.h"
#include "perception/grid_cell.h"
#include "perception/point_normals.h"

namespace relmap::perception {
namespace {

struct RawPoints {
  std::vector<Eigen::Vector3f> positions, normals;
};

// The voxel of `supervoxel` a point falls in. VCCS's grid is anchored at its first point, not
// at the origin, and is not kept, so the voxel is the one with the nearest centroid: a point
// lies within half a voxel of its own voxel's mean, nearly always nearer than to any other.
const Voxel* VoxelOf(const Supervoxel& supervoxel, const Eigen::Vector3f& point) {
  const Voxel* nearest = nullptr;
  float nearest_d2 = std::numeric_limits<float>::infinity();
  for (const Voxel& v : supervoxel.voxels) {
    const float d2 = (v.position - point).squaredNorm();
    if (d2 < nearest_d2) nearest_d2 = d2, nearest = &v;
  }
  return nearest;
}

// The raw points of one supervoxel, thinned to the first point per cell of `spacing` (0: all)
// and each given its voxel's VCCS normal; points whose voxel has no finite normal are left
// out, as the voxel schemes leave out that voxel (the normal is also what locates a voxel
// seen from too few points to be trusted). `seen` is scratch.
void CollectRawPoints(const Cloud& cloud, const Supervoxel& supervoxel, float spacing,
                      std::unordered_set<std::uint64_t>& seen, RawPoints& out) {
  seen.clear();
  const float inverse_spacing = spacing > 0.0f ? 1.0f / spacing : 0.0f;
  for (const std::int32_t index : supervoxel.point_indices) {
    const CloudPoint p = cloud.point(static_cast<std::size_t>(index));
    if (spacing > 0.0f && !seen.insert(GridCellKey(p.x, p.y, p.z, inverse_spacing)).second) {
      continue;
    }
    const Eigen::Vector3f position(p.x, p.y, p.z);
    const Voxel* voxel = VoxelOf(supervoxel, position);
    if (voxel == nullptr || !voxel->normal.allFinite()) continue;
    out.positions.push_back(position);
    out.normals.push_back(voxel->normal);
  }
}

// Replaces every voxel normal by the PCA normal of the raw points within `radius`, all
// supervoxels' points together (a neighbourhood crosses supervoxel borders); drops the
// points with too few neighbours for a normal.
void EstimateRawNormals(std::vector<RawPoints>& raw, float radius, int threads) {
  std::vector<Eigen::Vector3f> all;
  for (const RawPoints& r : raw) all.insert(all.end(), r.positions.begin(), r.positions.end());
  const std::vector<Eigen::Vector3f> normals = EstimateNormals(all, radius, threads);
  std::size_t next = 0;
  for (RawPoints& r : raw) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < r.positions.size(); ++i, ++next) {
      if (!normals[next].allFinite()) continue;
      r.positions[kept] = r.positions[i];
      r.normals[kept++] = normals[next];
    }
    r.positions.resize(kept);
    r.normals.resize(kept);
  }
}

}  // namespace

Eigen::MatrixXd SupervoxelFpfhRawPoints(const Cloud& cloud, const Segmentation& segmentation,
                                        const FeatureConfig& config, int threads) {
  const std::vector<Supervoxel>& svs = segmentation.supervoxels;
  const auto n = static_cast<std::ptrdiff_t>(svs.size());
  std::vector<RawPoints> raw(svs.size());
#pragma omp parallel num_threads(threads)
  {
    std::unordered_set<std::uint64_t> seen;
#pragma omp for schedule(dynamic, 16)
    for (std::ptrdiff_t s = 0; s < n; ++s) {
      const auto us = static_cast<std::size_t>(s);
      CollectRawPoints(cloud, svs[us], config.raw_point_spacing, seen, raw[us]);
    }
  }
  if (config.raw_normal_radius > 0.0f) EstimateRawNormals(raw, config.raw_normal_radius, threads);

  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, kFpfhDims);
  // One union per task, each with PointFpfh on one thread: unions are small and many, so
  // parallel unions keep both threads busy where one parallel PointFpfh would not.
#pragma omp parallel num_threads(threads)
  {
    std::vector<Eigen::Vector3f> positions, normals;
#pragma omp for schedule(dynamic, 4)
    for (std::ptrdiff_t s = 0; s < n; ++s) {
      const auto us = static_cast<std::size_t>(s);
      positions = raw[us].positions;
      normals = raw[us].normals;
      for (const std::uint32_t nb : svs[us].neighbours) {
        positions.insert(positions.end(), raw[nb].positions.begin(), raw[nb].positions.end());
        normals.insert(normals.end(), raw[nb].normals.begin(), raw[nb].normals.end());
      }
      if (positions.empty()) {
        out.row(s).setConstant(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      // §2: PointFpfh is already divided by 100; average over the union's points.
      const Eigen::MatrixXf fpfh = PointFpfh(positions, normals, config.fpfh_radius, 1);
      out.row(s) = fpfh.cast<double>().colwise().mean();
    }
  }
  return out;
}

}  // namespace relmap::perception
