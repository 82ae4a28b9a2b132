// SPLIT (§3.6): a component that overlaps the other class is cut in two along the
// gaps of its 1-nearest-neighbour graph, if that raises the likelihood.
#include <Eigen/Core>
#include <array>

#include "cmm/collaborative_mixture_models.h"
#include "cmm/partition.h"

namespace relmap::cmm {

bool CollaborativeMixtureModels::TrySplit(int label, int index, UpdateReport& report) {
  if (components_[label][index].size() <= dimension()) return false;  // no tolerance ellipsoid yet
  if (!OverlapsOtherClass(label, index)) return false;
  Component& c = components_[label][index];

  Eigen::MatrixXd points(dimension(), c.size());
  for (int j = 0; j < c.size(); ++j) points.col(j) = data_.sample(c.indices()[j]);
  const NearestNeighbourGraph& graph = c.NearestNeighbours(data_);
  const std::vector<int> group = PartitionInTwo(points, graph.nearest);
  if (group.empty()) return false;  // the 1-NN graph is connected

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
  std::vector<Component> halves;
  for (int h = 0; h < 2; ++h) {
    halves.push_back(Component::FromSamples(label, samples[h], data_, config_, prior_or_null()));
    halves.back().AdoptNearestNeighbours(std::move(halves_graph[h]));
  }
  if (!ImprovesLikelihood(label, {index}, halves, report)) return false;

  auto& mixture = components_[label];
  mixture[index] = std::move(halves[0]);
  mixture.push_back(std::move(halves[1]));
  RefreshWeights(label);
  ++splits_;
  ++report.splits;
  return true;
}

}  // namespace relmap::cmm
