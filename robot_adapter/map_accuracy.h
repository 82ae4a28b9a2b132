// How right a relevance map is, where the truth is known: the paper's soft accuracy
// (docs/method.md §6, exploration/metrics.h), the one score of relmap-robot's progress
// lines and learning curves.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "common/metrics.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::robot {

// nullopt when `moveable` does not have one entry per supervoxel of `maps`.
inline std::optional<double> MapAccuracy(const v1::ComputeMapsResponse& maps,
                                         const std::vector<bool>& moveable) {
  if (moveable.size() != static_cast<std::size_t>(maps.supervoxels_size())) return std::nullopt;
  Eigen::VectorXd relevance(maps.supervoxels_size());
  for (int i = 0; i < maps.supervoxels_size(); ++i) relevance[i] = maps.supervoxels(i).relevance();
  return metrics::SoftScores(relevance, moveable).accuracy;
}

}  // namespace relmap::robot
