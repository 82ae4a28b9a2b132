// Confidence (§4.2), the choice map and the draw of the next target (§4.3).
#pragma once

#include <Eigen/Core>

#include "cmm/collaborative_mixture_models.h"
#include "common/random.h"
#include "exploration/exploration_config.h"

namespace relmap::exploration {

// Per point: how well the dataset covers it, in [0, 1] (§4.2).
Eigen::VectorXd Confidence(const cmm::Evaluation& evaluation, ConfidenceMode mode);

// Per point: u(x) from the relevance and the class counts of the model (§4.1).
Eigen::VectorXd UncertaintyMap(const Eigen::VectorXd& relevance, int moveable_samples,
                               int non_moveable_samples, bool uncertainty_bug);

// The choice map: w_i = u_i (1 − c_i) normalised to sum 1, uniform when every w
// is 0 (§4.3). With `paper_quirks`, values below 1e-3 are zeroed first.
Eigen::VectorXd ChoiceMap(const Eigen::VectorXd& uncertainty, const Eigen::VectorXd& confidence,
                          bool paper_quirks);

// Per point, what a frame's choice map is made of (§4.3, §4.4).
struct ChoiceTerms {
  const Eigen::VectorXd& relevance;    // r
  const Eigen::VectorXd& uncertainty;  // u
  const Eigen::VectorXd& confidence;   // c
  const Eigen::VectorXd& novelty;      // g: all 1 without the diversity term
};

// The choice map of a session's exploration options (§4.4): the rule's weights
// (u_i (1 − c_i), or half per predicted class) times g_i,
// normalised, then mixed with the uniform map by `config.random_share`.
Eigen::VectorXd ChoiceMap(const ChoiceTerms& terms, const ExplorationConfig& config);

// Draws the index of the next target from a choice map with the session's RNG.
// `interactions` is the number of targets drawn before; with `paper_quirks`
// the first kPaperUniformChoices draws are uniform over all but the last index.
int DrawTarget(const Eigen::VectorXd& choice, int interactions, bool paper_quirks, Random& random);

}  // namespace relmap::exploration
