// precision = tp/(tp+fp), recall = tp/(tp+fn), accuracy = ½(tp/G_obj + tn/G_back).
#include "exploration/metrics.h"

#include <cassert>

namespace relmap::exploration {
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

}  // namespace relmap::exploration
