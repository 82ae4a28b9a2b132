// The two maps of a frame (§4): relevance (P(moveable) per supervoxel) and choice
// (probability of being the next push target), from one batched prediction, and
// the target drawn from the choice map.
#pragma once

#include <Eigen/Core>

#include "cmm/collaborative_mixture_models.h"
#include "common/random.h"
#include "exploration/exploration_config.h"

namespace relmap::exploration {

struct FrameMaps {
  Eigen::VectorXd relevance;    // per row; 0.5 for a row with a non-finite feature
  Eigen::VectorXd uncertainty;  // u (§4.1); 0 for such a row
  Eigen::VectorXd confidence;   // c (§4.2); 0 for such a row
  Eigen::VectorXd choice;       // sums to 1 over the usable rows; 0 for the others
  int target = -1;              // the drawn row; -1 when no row is usable
  int unusable_rows = 0;        // rows with a non-finite value, never given to the classifier
};

// Maps of the N×p feature matrix of a frame (one row per supervoxel). Rows with a
// non-finite value get relevance 0.5 and choice 0 (docs/method.md §2) and are
// counted. `interactions` is the number of targets drawn before in the session
// (the paper2018 quirks draw the first 11 uniformly); `random` is the session's RNG,
// or null to compute the maps without drawing a target (target stays -1).
FrameMaps ComputeFrameMaps(const cmm::CollaborativeMixtureModels& model,
                           const Eigen::Ref<const Eigen::MatrixXd>& features,
                           const ExplorationConfig& config, int interactions, Random* random);

}  // namespace relmap::exploration
