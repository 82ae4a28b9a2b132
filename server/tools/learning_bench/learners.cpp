// Name resolution only; each learner lives in its own file.
#include "learning_bench/learners.h"

#include <string>

#include "cmm/config_spec.h"
#include "learning_bench/averaged_logistic_sgd.h"
#include "learning_bench/cmm_learner.h"
#include "learning_bench/gaussian_naive_bayes.h"
#include "learning_bench/nearest_neighbours.h"

namespace relmap::learning_bench {
namespace {

StatusOr<cmm::CmmConfig> CmmConfigNamed(std::string_view name) {
  return cmm::ParseConfiguration(name == "alpha1" ? "corrected:alpha=1" : name);
}

}  // namespace

StatusOr<std::unique_ptr<OnlineLearner>> MakeLearner(std::string_view name, int dimension,
                                                     std::uint64_t seed) {
  if (name == "gnb") return std::unique_ptr<OnlineLearner>(new GaussianNaiveBayes(dimension));
  if (name == "sgd") return std::unique_ptr<OnlineLearner>(new AveragedLogisticSgd(dimension));
  if (name == "knn") return std::unique_ptr<OnlineLearner>(new NearestNeighbours(dimension));
  auto config = CmmConfigNamed(name);
  if (!config.ok()) {
    return InvalidArgumentError("unknown learner '" + std::string(name) + "' (" +
                                config.status().message() + "; or gnb, sgd, knn, alpha1)");
  }
  config->seed = seed;
  auto cmm = CmmLearner::Create(std::string(name), *config, dimension);
  if (!cmm.ok()) return cmm.status();
  return std::unique_ptr<OnlineLearner>(new CmmLearner(std::move(cmm).value()));
}

}  // namespace relmap::learning_bench
