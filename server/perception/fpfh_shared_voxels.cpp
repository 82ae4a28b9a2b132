// FPFH once per voxel over the whole voxel cloud, then the union mean per supervoxel: the
// fast scheme of §2's cost note. Each voxel's SPFH is computed once instead of ~7 times.
#include <cmath>
#include <cstdint>
#include <limits>

#include "perception/fpfh.h"
#include "perception/pair_batch.h"
#include "perception/radius_neighbours.h"

namespace relmap::perception {

Eigen::MatrixXf PointFpfh(const std::vector<Eigen::Vector3f>& positions,
                          const std::vector<Eigen::Vector3f>& normals, float radius, int threads) {
  const auto n = static_cast<std::ptrdiff_t>(positions.size());
  Eigen::MatrixXf fpfh = Eigen::MatrixXf::Zero(n, kFpfhDims);
  if (n == 0) return fpfh;
  // Everything below is in the table's row order; rows are ascending in every neighbour list.
  const RadiusNeighbours table = FindRadiusNeighbours(positions, radius, threads);
  const std::vector<std::size_t>& begin = table.begin;
  const std::vector<std::uint32_t>& neighbour = table.neighbour;
  std::vector<Eigen::Vector4f, Eigen::aligned_allocator<Eigen::Vector4f>> p4(positions.size()),
      n4(positions.size());
  for (std::size_t r = 0; r < positions.size(); ++r) {
    p4[r] << positions[table.order[r]], 0.0f;
    n4[r] << normals[table.order[r]], 0.0f;
  }

  // Pass 1: each unordered pair {i, j} is computed once, by i < j (the radius relation is
  // symmetric): code[e] is the pair as row i sees it, back[e] as j sees it.
  std::vector<PairCode> code(begin.back()), back(begin.back());
#pragma omp parallel num_threads(threads)
  {
    PairBatch batch;
    const auto store = [&](std::size_t e, PairCodes codes) {
      code[e] = codes.forward;
      back[e] = codes.backward;
    };
#pragma omp for schedule(dynamic, 64) nowait
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      for (std::size_t e = begin[ui]; e < begin[ui + 1]; ++e) {
        const std::uint32_t j = neighbour[e];
        if (j <= ui) continue;
        batch.Add(p4[ui], n4[ui], p4[j], n4[j], e);
        if (batch.full()) batch.Flush(store);
      }
    }
    batch.Flush(store);
  }
  // Row j lists its smaller neighbours first, ascending; visiting i ascending meets them in
  // that order, so a cursor per row places each backward code without a search.
  std::vector<std::size_t> cursor(begin.begin(), begin.end() - 1);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (std::size_t e = begin[i]; e < begin[i + 1]; ++e) {
      if (neighbour[e] > i) code[cursor[neighbour[e]]++] = back[e];
    }
  }
  // Pass 2: SPFH per point with PCL's normalisation 100 / (k - 1), the query point being
  // one of its k neighbours. Row-major, so that one point's 33 bins are contiguous.
  std::vector<float> spfh(positions.size() * kFpfhDims, 0.0f);
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    const std::size_t k = begin[ui + 1] - begin[ui];
    if (k < 2) continue;
    const float increment = 100.0f / static_cast<float>(k - 1);
    float* row = &spfh[ui * kFpfhDims];
    for (std::size_t e = begin[ui]; e < begin[ui + 1]; ++e) {
      if (neighbour[e] == ui) continue;
      const PairCode c = code[e];
      row[c / (kFpfhBins * kFpfhBins)] += increment;
      row[kFpfhBins + (c / kFpfhBins) % kFpfhBins] += increment;
      row[2 * kFpfhBins + c % kFpfhBins] += increment;
    }
  }
  // FPFH(i) = Σ_{j≠i} SPFH(j) / d²(i, j), each block normalised (FPFHEstimation's
  // weightPointSPFHSignature, which also leaves out the query point's own SPFH).
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    float sum[kFpfhDims] = {};
    for (std::size_t e = begin[ui]; e < begin[ui + 1]; ++e) {
      const std::uint32_t j = neighbour[e];
      const float d2 =
          FlannSquaredDistance(p4[ui].x(), p4[ui].y(), p4[ui].z(), p4[j].x(), p4[j].y(), p4[j].z());
      if (d2 == 0.0f) continue;
      const float weight = 1.0f / d2;
      const float* s = &spfh[static_cast<std::size_t>(j) * kFpfhDims];
      for (int b = 0; b < kFpfhDims; ++b) sum[b] += s[b] * weight;
    }
    const auto out = static_cast<Eigen::Index>(table.order[ui]);
    for (int block = 0; block < 3; ++block) {
      double total = 0.0;
      for (int b = 0; b < kFpfhBins; ++b) total += sum[block * kFpfhBins + b];
      if (total == 0.0) continue;
      for (int b = 0; b < kFpfhBins; ++b) {
        fpfh(out, block * kFpfhBins + b) = static_cast<float>(sum[block * kFpfhBins + b] / total);
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

Eigen::MatrixXd SupervoxelFpfh(const Cloud& cloud, const Segmentation& segmentation,
                               const FeatureConfig& config, int threads) {
  switch (config.fpfh_scheme) {
    case FpfhScheme::kExactUnion:
      return SupervoxelFpfhExactUnion(segmentation, config.fpfh_radius, threads);
    case FpfhScheme::kRawPoints:
      return SupervoxelFpfhRawPoints(cloud, segmentation, config, threads);
    case FpfhScheme::kSharedVoxels:
      break;
  }
  return SupervoxelFpfhSharedVoxels(segmentation, config.fpfh_radius, threads);
}

}  // namespace relmap::perception
