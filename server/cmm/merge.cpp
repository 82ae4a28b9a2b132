// MERGE (§3.7): a component that overlaps another of its class is replaced, with
// it, by their union, if that raises the likelihood.
#include "cmm/collaborative_mixture_models.h"

namespace relmap::cmm {
namespace {

// The 2018 code merged only components of at least this many samples.
constexpr int kPaperMinimumMergeSize = 5;

}  // namespace

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
    std::vector<Component> merged;
    merged.push_back(Component::Union(mixture[index], mixture[k], data_, config_, prior_or_null()));
    if (!ImprovesLikelihood(label, {index, k}, merged, report)) continue;
    mixture[index] = std::move(merged[0]);
    mixture.erase(mixture.begin() + k);
    RefreshWeights(label);
    ++merges_;
    ++report.merges;
    return true;
  }
  return false;
}

}  // namespace relmap::cmm
