// Relevance and choice maps of a frame: the usable rows are gathered into one
// matrix and evaluated in a single batched pass over the components.
#include "exploration/frame_maps.h"

#include <vector>

#include "exploration/choice.h"
#include "exploration/novelty.h"

namespace relmap::exploration {

FrameMaps ComputeFrameMaps(const cmm::CollaborativeMixtureModels& model,
                           const Eigen::Ref<const Eigen::MatrixXd>& features,
                           const ExplorationConfig& config, int interactions, Random* random) {
  const Eigen::Index n = features.rows();
  std::vector<Eigen::Index> usable;
  usable.reserve(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    if (features.row(i).allFinite()) usable.push_back(i);
  }

  FrameMaps maps;
  maps.unusable_rows = static_cast<int>(n - static_cast<Eigen::Index>(usable.size()));
  maps.relevance = Eigen::VectorXd::Constant(n, 0.5);
  maps.uncertainty = Eigen::VectorXd::Zero(n);
  maps.confidence = Eigen::VectorXd::Zero(n);
  maps.choice = Eigen::VectorXd::Zero(n);
  if (usable.empty()) return maps;

  const auto m = static_cast<Eigen::Index>(usable.size());
  Eigen::MatrixXd rows(m, features.cols());
  for (Eigen::Index j = 0; j < m; ++j) rows.row(j) = features.row(usable[j]);
  const cmm::Evaluation evaluation = model.Evaluate(rows);
  const Eigen::VectorXd u = UncertaintyMap(evaluation.relevance, model.sample_count(1),
                                           model.sample_count(0), config.uncertainty_bug);
  const Eigen::VectorXd c = Confidence(evaluation, config.confidence);
  const Eigen::VectorXd g = config.diversity == Diversity::kNovelty ? Novelty(rows, model.dataset())
                                                                    : Eigen::VectorXd::Ones(m);
  const Eigen::VectorXd choice = ChoiceMap({evaluation.relevance, u, c, g}, config);

  for (Eigen::Index j = 0; j < m; ++j) {
    maps.relevance[usable[j]] = evaluation.relevance[j];
    maps.uncertainty[usable[j]] = u[j];
    maps.confidence[usable[j]] = c[j];
    maps.choice[usable[j]] = choice[j];
  }
  if (random != nullptr) {
    const int drawn = DrawTarget(choice, interactions, config.paper_choice_quirks, *random);
    maps.target = static_cast<int>(usable[static_cast<std::size_t>(drawn)]);
  }
  return maps;
}

}  // namespace relmap::exploration
