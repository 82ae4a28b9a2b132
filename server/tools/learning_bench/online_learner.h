// The one interface every learner of the learning benchmark implements: learn
// one labelled sample at a time, in stream order, and predict P(moveable | x).
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::learning_bench {

class OnlineLearner {
 public:
  virtual ~OnlineLearner() = default;

  // Takes one sample (label 0 or 1). An input the learner rejects → an error,
  // and the learner is unchanged.
  virtual Status Learn(const Eigen::Ref<const Eigen::VectorXd>& x, int label) = 0;
  // P(label = 1 | x) for every row of `points`, 0.5 before any sample. Batched
  // because a robot scores every supervoxel of a frame at once.
  virtual Eigen::VectorXd Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const = 0;
  // The name the benchmark table shows (the name it was made from).
  virtual std::string Name() const = 0;
  // Mixture components of class 0 and class 1; nullopt for a learner without.
  virtual std::optional<std::array<int, 2>> Components() const { return std::nullopt; }
};

// What Learn accepts: `dimension` finite values and a label 0 or 1.
inline Status CheckSample(std::string_view learner, const Eigen::Ref<const Eigen::VectorXd>& x,
                          int label, Eigen::Index dimension) {
  if (x.size() != dimension || !x.allFinite() || (label != 0 && label != 1)) {
    return InvalidArgumentError(std::string(learner) + ": expected " + std::to_string(dimension) +
                                " finite values and a label 0 or 1");
  }
  return OkStatus();
}

}  // namespace relmap::learning_bench
