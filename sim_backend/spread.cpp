// Iteration k of every replication is its record k − 1: replications record every
// iteration in order, and one that stopped early simply has fewer.
#include "spread.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace relmap::sim {

std::optional<Spread> SpreadOf(const std::vector<double>& values) {
  Spread spread{0, INFINITY, -INFINITY};
  std::size_t count = 0;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    spread.mean += v, spread.min = std::min(spread.min, v), spread.max = std::max(spread.max, v);
    ++count;
  }
  if (count == 0) return std::nullopt;
  spread.mean /= static_cast<double>(count);
  return spread;
}

IterationTimings MeanTimings(const std::vector<ReplicationResult>& replications,
                             std::size_t* iterations) {
  IterationTimings mean;
  double* const stages[] = {&mean.respawn_ms,     &mean.capture_ms,    &mean.maps_ms,
                            &mean.server_maps_ms, &mean.evaluation_ms, &mean.snapshot_ms,
                            &mean.push_ms,        &mean.outcome_ms,    &mean.iteration_ms};
  std::size_t count = 0;
  for (const ReplicationResult& r : replications) {
    for (const IterationRecord& i : r.iterations) {
      const IterationTimings& t = i.timings;
      const double values[] = {t.respawn_ms,     t.capture_ms,    t.maps_ms,
                               t.server_maps_ms, t.evaluation_ms, t.snapshot_ms,
                               t.push_ms,        t.outcome_ms,    t.iteration_ms};
      for (std::size_t k = 0; k < std::size(values); ++k) *stages[k] += values[k];
      ++count;
    }
  }
  if (count > 0) {
    for (double* stage : stages) *stage /= static_cast<double>(count);
  }
  *iterations = count;
  return mean;
}

Envelope EnvelopeOver(const std::vector<ReplicationResult>& replications,
                      const std::function<std::optional<double>(const IterationRecord&)>& of) {
  std::size_t iterations = 0;
  for (const ReplicationResult& r : replications) {
    iterations = std::max(iterations, r.iterations.size());
  }
  Envelope envelope;
  std::vector<double> values;
  for (std::size_t k = 0; k < iterations; ++k) {
    values.clear();
    for (const ReplicationResult& r : replications) {
      if (k >= r.iterations.size()) continue;
      if (const std::optional<double> value = of(r.iterations[k])) values.push_back(*value);
    }
    const std::optional<Spread> spread = SpreadOf(values);
    if (!spread) continue;
    envelope.x.push_back(static_cast<double>(k + 1));
    envelope.mean.push_back(spread->mean);
    envelope.low.push_back(spread->min);
    envelope.high.push_back(spread->max);
  }
  return envelope;
}

}  // namespace relmap::sim
