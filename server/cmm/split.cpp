// SPLIT (§3.6): a component that overlaps the other class is cut in two along the
// gaps of its 1-nearest-neighbour graph, if that raises the likelihood.
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "cmm/partition.h"

namespace relmap::cmm {

bool CollaborativeMixtureModels::TrySplit(int label, int index, UpdateReport& report) {
  if (components_[label][index].size() <= dimension()) return false;  // no tolerance ellipsoid yet
  if (!OverlapsOtherClass(label, index)) return false;
  std::optional<std::vector<Component>>& halves = components_[label][index].cached_split();
  if (!halves) halves = SplitHalves(components_[label][index]);
  if (halves->empty()) return false;  // the 1-NN graph is connected
  // The cached halves themselves are evaluated, so that their columns are kept too.
  if (!ImprovesLikelihood(label, {index}, *halves, report)) return false;

  std::vector<Component> accepted = std::move(*halves);
  auto& mixture = components_[label];
  mixture[index] = std::move(accepted[0]);
  mixture.push_back(std::move(accepted[1]));
  RefreshWeights(label);
  ++splits_;
  ++report.splits;
  return true;
}

std::vector<Component> CollaborativeMixtureModels::SplitHalves(Component& c) {
  const int label = c.label();
  const NearestNeighbourGraph& graph = c.NearestNeighbours(data_);
  const std::vector<int> group = PartitionInTwo(data_, c.indices(), graph.nearest);
  if (group.empty()) return {};

  // Each half keeps its samples in the parent's order, and inherits the
  // parent's 1-NN graph: groups are unions of the graph's connected components.
  std::array<std::vector<int>, 2> samples;
  std::array<NearestNeighbourGraph, 2> halves_graph;
  std::vector<int> position_in_half(c.size());
  for (int j = 0; j < c.size(); ++j) {
    position_in_half[j] = static_cast<int>(samples[group[j]].size());
    samples[group[j]].push_back(c.indices()[j]);
  }
  for (int j = 0; j < c.size(); ++j) {
    halves_graph[group[j]].nearest.push_back(position_in_half[graph.nearest[j]]);
    halves_graph[group[j]].squared_distance.push_back(graph.squared_distance[j]);
  }
  // A half of the component before it grew that is again a half, the same
  // samples in the same order, is kept with its column: it is what
  // FromSamples would rebuild.
  std::vector<Component> earlier = c.TakeEarlierHalves();
  std::vector<Component> halves;
  halves.reserve(2);
  for (int h = 0; h < 2; ++h) {
    const auto same = std::find_if(earlier.begin(), earlier.end(),
                                   [&](const Component& e) { return e.indices() == samples[h]; });
    if (same != earlier.end()) {
      halves.push_back(std::move(*same));
    } else {
      halves.push_back(Component::FromSamples(label, samples[h], data_, config_, prior_or_null()));
    }
    halves.back().AdoptNearestNeighbours(std::move(halves_graph[h]));
  }
  return halves;
}

}  // namespace relmap::cmm
