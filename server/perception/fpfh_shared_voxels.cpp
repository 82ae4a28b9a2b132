// FPFH once per voxel over the whole voxel cloud, then the union mean per supervoxel: the
// fast scheme of §2's cost note. Each voxel's SPFH is computed once instead of ~7 times.
#include <pcl/features/pfh_tools.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "perception/fpfh.h"

namespace relmap::perception {
namespace {

constexpr std::uint16_t kNoPair = 0xffff;

// PCL's SPFH binning of one pair (FPFHEstimation::computePointSPFHSignature), same
// expressions and types, packed as b1 * 121 + b2 * 11 + b3; kNoPair when PCL skips the pair.
std::uint16_t PairBins(const Eigen::Vector4f& p1, const Eigen::Vector4f& n1,
                       const Eigen::Vector4f& p2, const Eigen::Vector4f& n2) {
  float f1, f2, f3, f4;
  if (!pcl::computePairFeatures(p1, n1, p2, n2, f1, f2, f3, f4)) return kNoPair;
  constexpr float kInverseTwoPi = 1.0f / (2.0f * static_cast<float>(M_PI));
  const auto bin = [](double scaled) {
    const int b = static_cast<int>(std::floor(kFpfhBins * scaled));
    return b < 0 ? 0 : (b >= kFpfhBins ? kFpfhBins - 1 : b);
  };
  return static_cast<std::uint16_t>(bin((f1 + M_PI) * kInverseTwoPi) * kFpfhBins * kFpfhBins +
                                    bin((f2 + 1.0) * 0.5) * kFpfhBins + bin((f3 + 1.0) * 0.5));
}

// computePairFeatures(i, j) and (j, i) give the same features unless PCL's choice of the
// source point ties (equal acos of the two normal angles); then both orders are computed.
bool PairIsSymmetric(const Eigen::Vector4f& p1, const Eigen::Vector4f& n1,
                     const Eigen::Vector4f& p2, const Eigen::Vector4f& n2) {
  const Eigen::Vector4f d = p2 - p1;
  const float f4 = d.norm();
  return std::acos(std::fabs(n1.dot(d) / f4)) != std::acos(std::fabs(n2.dot(d) / f4));
}

}  // namespace

Eigen::MatrixXf PointFpfh(const std::vector<Eigen::Vector3f>& positions,
                          const std::vector<Eigen::Vector3f>& normals, float radius, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(positions.size());
  Eigen::MatrixXf fpfh = Eigen::MatrixXf::Zero(n, kFpfhDims);
  if (n == 0) return fpfh;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize(positions.size());
  std::vector<Eigen::Vector4f, Eigen::aligned_allocator<Eigen::Vector4f>> p4(positions.size()),
      n4(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    (*cloud)[i].getVector3fMap() = positions[i];
    p4[i] << positions[i], 0.0f;
    n4[i] << normals[i], 0.0f;
  }
  // Unsorted results: sorting by distance costs 1.5-3x (TOOLCHAIN); we sort by index below.
  pcl::KdTreeFLANN<pcl::PointXYZ> tree(/*sorted=*/false);
  tree.setInputCloud(cloud);

  // Pass 1: one radius search per point, neighbours sorted by index. The radius relation is
  // symmetric, so each unordered pair {i, j} is computed once, by the smaller index.
  std::vector<pcl::Indices> neighbours(positions.size());
  std::vector<std::vector<float>> sq_distances(positions.size());
  // bins[i][k]: low 16 bits the pair (i, neighbours[i][k]) as i sees it, high 16 bits as
  // the neighbour sees it; filled for neighbours[i][k] > i only.
  std::vector<std::vector<std::uint32_t>> bins(positions.size());
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices found;
    std::vector<float> found_d2;
    std::vector<std::size_t> order;
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      tree.radiusSearch((*cloud)[ui], radius, found, found_d2);
      order.resize(found.size());
      for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
      std::sort(order.begin(), order.end(), [&](auto a, auto b) { return found[a] < found[b]; });
      neighbours[ui].resize(found.size());
      sq_distances[ui].resize(found.size());
      bins[ui].assign(found.size(), 0);
      for (std::size_t k = 0; k < order.size(); ++k) {
        neighbours[ui][k] = found[order[k]];
        sq_distances[ui][k] = found_d2[order[k]];
        const auto j = static_cast<std::size_t>(neighbours[ui][k]);
        if (j <= ui) continue;
        const std::uint16_t forward = PairBins(p4[ui], n4[ui], p4[j], n4[j]);
        const std::uint16_t backward = PairIsSymmetric(p4[ui], n4[ui], p4[j], n4[j])
                                           ? forward
                                           : PairBins(p4[j], n4[j], p4[ui], n4[ui]);
        bins[ui][k] = forward | static_cast<std::uint32_t>(backward) << 16;
      }
    }
  }
  // Pass 2: SPFH per point with PCL's normalisation 100 / (k - 1), the query point being
  // one of its k neighbours. Row-major, so that one point's 33 bins are contiguous.
  std::vector<float> spfh(positions.size() * kFpfhDims, 0.0f);
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    const pcl::Indices& nb = neighbours[ui];
    if (nb.size() < 2) continue;
    const float increment = 100.0f / static_cast<float>(nb.size() - 1);
    float* row = &spfh[ui * kFpfhDims];
    for (std::size_t k = 0; k < nb.size(); ++k) {
      const auto j = static_cast<std::size_t>(nb[k]);
      std::uint16_t code;
      if (j == ui) continue;
      if (j > ui) {
        code = static_cast<std::uint16_t>(bins[ui][k] & 0xffff);
      } else {
        const pcl::Indices& back = neighbours[j];
        const auto it = std::lower_bound(back.begin(), back.end(), static_cast<int>(ui));
        code = it != back.end() && *it == static_cast<int>(ui)
                   ? static_cast<std::uint16_t>(
                         bins[j][static_cast<std::size_t>(it - back.begin())] >> 16)
                   : PairBins(p4[ui], n4[ui], p4[j], n4[j]);
      }
      if (code == kNoPair) continue;
      row[code / (kFpfhBins * kFpfhBins)] += increment;
      row[kFpfhBins + (code / kFpfhBins) % kFpfhBins] += increment;
      row[2 * kFpfhBins + code % kFpfhBins] += increment;
    }
  }
  // FPFH(i) = Σ_{j≠i} SPFH(j) / d²(i, j), each block normalised (FPFHEstimation's
  // weightPointSPFHSignature, which also leaves out the query point's own SPFH).
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    float sum[kFpfhDims] = {};
    for (std::size_t k = 0; k < neighbours[ui].size(); ++k) {
      const float d2 = sq_distances[ui][k];
      if (d2 == 0.0f) continue;
      const float weight = 1.0f / d2;
      const float* s = &spfh[static_cast<std::size_t>(neighbours[ui][k]) * kFpfhDims];
      for (int b = 0; b < kFpfhDims; ++b) sum[b] += s[b] * weight;
    }
    for (int block = 0; block < 3; ++block) {
      double total = 0.0;
      for (int b = 0; b < kFpfhBins; ++b) total += sum[block * kFpfhBins + b];
      if (total == 0.0) continue;
      for (int b = 0; b < kFpfhBins; ++b) {
        fpfh(i, block * kFpfhBins + b) = static_cast<float>(sum[block * kFpfhBins + b] / total);
      }
    }
  }
  return fpfh;
}

Eigen::MatrixXd SupervoxelFpfhSharedVoxels(const Segmentation& segmentation, float radius,
                                           int threads) {
  const std::vector<Supervoxel>& svs = segmentation.supervoxels;
  // All voxels with a finite normal, supervoxel after supervoxel.
  std::vector<Eigen::Vector3f> positions, normals;
  std::vector<std::size_t> begin(svs.size() + 1, 0);
  for (std::size_t s = 0; s < svs.size(); ++s) {
    begin[s] = positions.size();
    for (const Voxel& v : svs[s].voxels) {
      if (!v.normal.allFinite()) continue;
      positions.push_back(v.position);
      normals.push_back(v.normal);
    }
  }
  begin[svs.size()] = positions.size();
  const Eigen::MatrixXf voxel_fpfh = PointFpfh(positions, normals, radius, threads);

  // Per supervoxel, the sum over its own voxels; the union mean adds the neighbours' sums.
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(svs.size()), kFpfhDims);
  for (std::size_t s = 0; s < svs.size(); ++s) {
    for (std::size_t v = begin[s]; v < begin[s + 1]; ++v) {
      sums.row(static_cast<Eigen::Index>(s)) +=
          voxel_fpfh.row(static_cast<Eigen::Index>(v)).cast<double>();
    }
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>(svs.size()), kFpfhDims);
  for (std::size_t s = 0; s < svs.size(); ++s) {
    const auto row = static_cast<Eigen::Index>(s);
    out.row(row) = sums.row(row);
    std::size_t count = begin[s + 1] - begin[s];
    for (std::uint32_t nb : svs[s].neighbours) {
      out.row(row) += sums.row(static_cast<Eigen::Index>(nb));
      count += begin[nb + 1] - begin[nb];
    }
    if (count == 0) {
      out.row(row).setConstant(std::numeric_limits<double>::quiet_NaN());
    } else {
      out.row(row) /= static_cast<double>(count);
    }
  }
  return out;
}

void CollectUnionVoxels(const Segmentation& segmentation, const Supervoxel& supervoxel,
                        std::vector<Eigen::Vector3f>& positions,
                        std::vector<Eigen::Vector3f>& normals) {
  positions.clear();
  normals.clear();
  const auto add = [&](const Supervoxel& sv) {
    for (const Voxel& v : sv.voxels) {
      if (!v.normal.allFinite()) continue;
      positions.push_back(v.position);
      normals.push_back(v.normal);
    }
  };
  add(supervoxel);
  for (std::uint32_t nb : supervoxel.neighbours) add(segmentation.supervoxels[nb]);
}

Eigen::MatrixXd SupervoxelFpfh(const Segmentation& segmentation, FpfhScheme scheme, float radius,
                               int threads) {
  return scheme == FpfhScheme::kExactUnion
             ? SupervoxelFpfhExactUnion(segmentation, radius, threads)
             : SupervoxelFpfhSharedVoxels(segmentation, radius, threads);
}

}  // namespace relmap::perception
