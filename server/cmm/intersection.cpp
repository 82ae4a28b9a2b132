// The tolerance-ellipsoid intersection tests (§3.5) and the candidate orders
// that SPLIT and MERGE walk through.
#include <algorithm>
#include <numeric>
#include <span>

#include "cmm/collaborative_mixture_models.h"

namespace relmap::cmm {

bool CollaborativeMixtureModels::Intersects(const Component& c, const Component& candidate) {
  // (ρ − μ)ᵀ Σ⁻¹ (ρ − μ) <= T(n, p, α), with C's covariance and C′'s mean ρ.
  const double threshold = tolerance_(c.size());
  if (threshold <= 0.0) return false;  // n <= p or α = 1: no ellipsoid
  return InsideTolerance(c.SquaredMahalanobis(candidate.centre()), threshold);
}

bool CollaborativeMixtureModels::OverlapsOtherClass(int label, int index) {
  const int other = 1 - label;
  Component& c = components_[label][index];
  if (config_.split_overlap == SplitOverlap::kOtherSamples) {
    // Any other-class sample inside C's ellipsoid, read off C's cached column.
    const double threshold = tolerance_(c.size());
    const std::span<const double> column = c.LogDensityColumn(data_);
    for (int i = 0; i < data_.size(); ++i) {
      if (data_.label(i) == other &&
          InsideTolerance(c.SquaredDistanceFromLogDensity(column[i]), threshold)) {
        return true;
      }
    }
    return false;
  }
  // Candidates: every other-class component (paper Alg. 2), or only the one
  // nearest to C in C's metric (switch nearest_candidate_only).
  std::vector<int> candidates = CandidatesByDistance(c, other, -1);
  if (config_.switches.nearest_candidate_only && candidates.size() > 1)
    candidates.erase(candidates.begin() + 1, candidates.end());
  for (int k : candidates) {
    if (Intersects(c, components_[other][k])) return true;
  }
  return false;
}

std::vector<int> CollaborativeMixtureModels::CandidatesByDistance(const Component& c, int label,
                                                                  int skip) const {
  const auto& mixture = components_[label];
  std::vector<int> order;
  order.reserve(mixture.size());
  std::vector<double> distance(mixture.size());
  for (int k = 0; k < static_cast<int>(mixture.size()); ++k) {
    if (k == skip) continue;
    distance[k] = c.SquaredMahalanobis(mixture[k].centre());
    order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return distance[a] < distance[b]; });
  return order;
}

}  // namespace relmap::cmm
