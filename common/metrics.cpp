// precision = tp/(tp+fp), recall = tp/(tp+fn), accuracy = ½(tp/G_obj + tn/G_back).
#include "common/metrics.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace relmap::metrics {
namespace {

struct Counts {
  double tp = 0, tn = 0, fp = 0, fn = 0;
  double objects = 0, background = 0;  // G_obj = Σ(1−δ), G_back = Σδ
};

std::optional<double> Ratio(double numerator, double denominator) {
  if (denominator == 0.0) return std::nullopt;
  return numerator / denominator;
}

Scores FromCounts(const Counts& c) {
  Scores s;
  s.precision = Ratio(c.tp, c.tp + c.fp);
  s.recall = Ratio(c.tp, c.tp + c.fn);
  const auto object_rate = Ratio(c.tp, c.objects);
  const auto background_rate = Ratio(c.tn, c.background);
  if (object_rate && background_rate) s.accuracy = 0.5 * (*object_rate + *background_rate);
  return s;
}

}  // namespace

Scores SoftScores(const Eigen::VectorXd& relevance, const std::vector<bool>& moveable) {
  assert(static_cast<std::size_t>(relevance.size()) == moveable.size());
  Counts c;
  for (Eigen::Index i = 0; i < relevance.size(); ++i) {
    const double p1 = relevance[i];
    if (moveable[static_cast<std::size_t>(i)]) {
      c.tp += p1, c.fn += 1.0 - p1, c.objects += 1.0;
    } else {
      c.fp += p1, c.tn += 1.0 - p1, c.background += 1.0;
    }
  }
  return FromCounts(c);
}

Scores ThresholdedSoftScores(const Eigen::VectorXd& relevance, const std::vector<bool>& moveable,
                             double threshold) {
  assert(static_cast<std::size_t>(relevance.size()) == moveable.size());
  Counts c;
  for (Eigen::Index i = 0; i < relevance.size(); ++i) {
    const double p1 = relevance[i];
    const bool above = p1 >= threshold;
    if (moveable[static_cast<std::size_t>(i)]) {
      (above ? c.tp : c.fn) += above ? p1 : 1.0 - p1;
      c.objects += 1.0;
    } else {
      (above ? c.fp : c.tn) += above ? p1 : 1.0 - p1;
      c.background += 1.0;
    }
  }
  return FromCounts(c);
}

std::optional<double> BalancedAccuracy(const Eigen::VectorXd& relevance,
                                       const std::vector<bool>& moveable, double threshold) {
  assert(static_cast<std::size_t>(relevance.size()) == moveable.size());
  double right[2] = {0, 0}, total[2] = {0, 0};  // indexed by the true class
  for (Eigen::Index i = 0; i < relevance.size(); ++i) {
    const int truth = moveable[static_cast<std::size_t>(i)] ? 1 : 0;
    total[truth] += 1.0;
    right[truth] += (relevance[i] >= threshold) == (truth == 1) ? 1.0 : 0.0;
  }
  const auto recall_0 = Ratio(right[0], total[0]);
  const auto recall_1 = Ratio(right[1], total[1]);
  if (!recall_0 || !recall_1) return std::nullopt;
  return 0.5 * (*recall_0 + *recall_1);
}

std::optional<double> LogLoss(const Eigen::VectorXd& relevance, const std::vector<bool>& moveable) {
  assert(static_cast<std::size_t>(relevance.size()) == moveable.size());
  constexpr double kClip = 1e-15;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < relevance.size(); ++i) {
    const double p1 = std::clamp(relevance[i], kClip, 1.0 - kClip);
    sum -= std::log(moveable[static_cast<std::size_t>(i)] ? p1 : 1.0 - p1);
  }
  return Ratio(sum, static_cast<double>(relevance.size()));
}

std::optional<double> BrierScore(const Eigen::VectorXd& relevance,
                                 const std::vector<bool>& moveable) {
  assert(static_cast<std::size_t>(relevance.size()) == moveable.size());
  double sum = 0.0;
  for (Eigen::Index i = 0; i < relevance.size(); ++i) {
    const double error = relevance[i] - (moveable[static_cast<std::size_t>(i)] ? 1.0 : 0.0);
    sum += error * error;
  }
  return Ratio(sum, static_cast<double>(relevance.size()));
}

}  // namespace relmap::metrics
