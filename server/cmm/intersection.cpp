// The tolerance-ellipsoid intersection test (§3.5) and the candidate orders that
// SPLIT and MERGE walk through.
#include <algorithm>
#include <numeric>

#include "cmm/collaborative_mixture_models.h"

namespace relmap::cmm {

bool CollaborativeMixtureModels::Intersects(const Component& c, const Component& candidate) {
  // (ρ − μ)ᵀ Σ⁻¹ (ρ − μ) <= T(n, p, α), with C's covariance and C′'s mean ρ.
  const double threshold = tolerance_(c.size());
  if (threshold <= 0.0) return false;  // n <= p or α = 1: no ellipsoid
  return InsideTolerance(c.SquaredMahalanobis(candidate.centre()), threshold);
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
