// Novelty of a frame's supervoxels against what the session has already labelled
// (docs/method.md §4.4): the diversity term of the choice map.
#pragma once

#include <Eigen/Core>

#include "cmm/dataset.h"

namespace relmap::exploration {

// Per candidate row: g_i = d_i² / (d_i² + h²) in [0, 1), where d_i is the
// distance from row i to its nearest labelled sample in the standardised feature
// space (each dimension divided by the labelled samples' standard deviation
// there, floored), and h² is the median of the d_i² over the candidates. A row
// that repeats a labelled sample gets 0, the frame's median row ½, a row far from
// every sample → 1. All 1 when fewer than two samples are labelled (no scale yet).
Eigen::VectorXd Novelty(const Eigen::Ref<const Eigen::MatrixXd>& candidates,
                        const cmm::Dataset& labelled);

}  // namespace relmap::exploration
