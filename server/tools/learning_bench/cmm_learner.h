// Collaborative Mixture Models behind the benchmark's learner interface.
#pragma once

#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "learning_bench/online_learner.h"

namespace relmap::learning_bench {

class CmmLearner final : public OnlineLearner {
 public:
  // An empty model of `config`; `name` is what the table shows.
  static StatusOr<CmmLearner> Create(std::string name, const cmm::CmmConfig& config, int dimension);

  Status Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) override;
  Eigen::VectorXd Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const override;
  std::string Name() const override { return name_; }
  std::optional<std::array<int, 2>> Components() const override;

 private:
  CmmLearner(std::string name, cmm::CollaborativeMixtureModels model)
      : name_(std::move(name)), model_(std::move(model)) {}

  std::string name_;
  cmm::CollaborativeMixtureModels model_;
};

}  // namespace relmap::learning_bench
