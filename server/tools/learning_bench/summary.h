// From the runs of one learner on the replications of one stream to a table
// row and a learning curve with its min–max envelope; the best learner of a
// stream.
#pragma once

#include <string>
#include <vector>

#include "learning_bench/evaluation.h"
#include "learning_bench/table_row.h"

namespace relmap::learning_bench {

// Mean (and min) over the runs where a score is defined; undefined where no run
// defines it. Latency percentiles pool every update of every run.
TableRow Summarise(const std::string& stream, const std::string& learner,
                   const std::vector<RunResult>& runs, const tools::LatencyRecorder& updates);

// Balanced accuracy against training samples, over the replications.
struct CurveSummary {
  std::string stream;
  std::string learner;
  std::vector<double> samples, mean, min, max;
};

// Points where any run is undefined are left out; runs of unequal length keep
// the common prefix.
CurveSummary SummariseCurves(const std::string& stream, const std::string& learner,
                             const std::vector<RunResult>& runs);

// The best online learner of a stream: the highest mean balanced accuracy, ties
// to the lower log-loss; and the best batch reference if it beats that.
struct StreamBest {
  std::string stream;
  std::optional<TableRow> online;     // none if no row of the stream has a score
  std::optional<TableRow> reference;  // set only if it scores higher than `online`
};

// One entry per stream, in the order of `streams`; rows whose learner is named
// in `references` count as batch references.
std::vector<StreamBest> BestPerStream(const std::vector<TableRow>& rows,
                                      const std::vector<std::string>& streams,
                                      const std::vector<std::string>& references);

}  // namespace relmap::learning_bench
