// A thin adapter: Add and Predict of the model, nothing of its own.
#include "learning_bench/cmm_learner.h"

namespace relmap::learning_bench {

StatusOr<CmmLearner> CmmLearner::Create(std::string name, const cmm::CmmConfig& config,
                                        int dimension) {
  auto model = cmm::CollaborativeMixtureModels::Create(config, dimension);
  if (!model.ok()) return model.status();
  return CmmLearner(std::move(name), std::move(model).value());
}

Status CmmLearner::Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) {
  return model_.Add(x, label).status();
}

Eigen::VectorXd CmmLearner::Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const {
  return model_.Predict(points);
}

std::optional<std::array<int, 2>> CmmLearner::Components() const {
  return std::array<int, 2>{model_.component_count(0), model_.component_count(1)};
}

}  // namespace relmap::learning_bench
