// MERGE (§3.7): a component that overlaps another of its class is replaced, with
// it, by their union, if that raises the likelihood.
#include <algorithm>
#include <vector>

#include "cmm/collaborative_mixture_models.h"

namespace relmap::cmm {
namespace {

// The 2018 code merged only components of at least this many samples.
constexpr int kPaperMinimumMergeSize = 5;

// Unions a component keeps (Component::cached_unions), its nearest partners
// being the ones MERGE tries first.
constexpr std::size_t kCachedUnions = 4;

}  // namespace

std::vector<Component>& CollaborativeMixtureModels::UnionCandidate(int label, int index, int k) {
  auto& mixture = components_[label];
  auto& unions = mixture[index].cached_unions();
  const std::uint64_t partner = mixture[k].version();
  for (Component::CachedUnion& u : unions) {
    if (u.partner_version == partner) return u.merged;
  }
  // Forget the unions with components that have changed since, then the oldest.
  std::erase_if(unions, [&](const Component::CachedUnion& u) {
    return std::none_of(mixture.begin(), mixture.end(),
                        [&](const Component& c) { return c.version() == u.partner_version; });
  });
  if (unions.size() >= kCachedUnions) unions.erase(unions.begin());
  Component::CachedUnion& u = unions.emplace_back();
  u.partner_version = partner;
  u.merged.push_back(Component::Union(mixture[index], mixture[k], data_, config_, prior_or_null()));
  return u.merged;
}

bool CollaborativeMixtureModels::TryMerge(int label, int index, UpdateReport& report) {
  auto& mixture = components_[label];
  if (mixture[index].size() <= dimension()) return false;  // no tolerance ellipsoid yet

  // Candidates nearest first; `index` is skipped, so C never merges with itself.
  std::vector<int> candidates = CandidatesByDistance(mixture[index], label, index);
  if (config_.switches.nearest_candidate_only) {
    if (candidates.size() > 1) candidates.erase(candidates.begin() + 1, candidates.end());
    if (!candidates.empty() && (mixture[index].size() < kPaperMinimumMergeSize ||
                                mixture[candidates[0]].size() < kPaperMinimumMergeSize)) {
      return false;
    }
  }
  int evaluated = 0;
  for (int k : candidates) {
    if (!Intersects(mixture[index], mixture[k])) continue;
    // Bounded work per update: the nearest intersecting candidates only; the
    // random re-check of §3.4 reaches the others over later updates.
    if (config_.max_merge_candidates > 0 && evaluated++ >= config_.max_merge_candidates) break;
    // A union evaluated before, of the same two states, comes with its column.
    std::vector<Component>& merged = UnionCandidate(label, index, k);
    if (!ImprovesLikelihood(label, {index, k}, merged, report)) continue;
    Component accepted = std::move(merged[0]);  // out of mixture[index]'s cache first
    mixture[index] = std::move(accepted);
    mixture.erase(mixture.begin() + k);
    RefreshWeights(label);
    ++merges_;
    ++report.merges;
    return true;
  }
  return false;
}

}  // namespace relmap::cmm
