// Mean, minimum and maximum over replications: of the final scores in the summary,
// and of every iteration's value in the plotted curves (the paper's mean with a
// min–max envelope); and the mean time of an iteration's stages.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "iteration_record.h"

namespace relmap::sim {

struct Spread {
  double mean = 0;
  double min = 0;
  double max = 0;
};

// Of the defined values; nullopt when there is none.
std::optional<Spread> SpreadOf(const std::vector<double>& values);

// A curve over iterations: at x[k], the spread over the replications that have a
// defined value there.
struct Envelope {
  std::vector<double> x;
  std::vector<double> mean;
  std::vector<double> low;
  std::vector<double> high;
};

// The mean of every stage's time over every recorded iteration of every replication
// (all zero when there is none); `iterations` receives how many were averaged.
IterationTimings MeanTimings(const std::vector<ReplicationResult>& replications,
                             std::size_t* iterations);

// Iterations at which no replication has a value (`of` gives nullopt: an undefined
// score, §6) are left out of the curve.
Envelope EnvelopeOver(const std::vector<ReplicationResult>& replications,
                      const std::function<std::optional<double>(const IterationRecord&)>& of);

}  // namespace relmap::sim
