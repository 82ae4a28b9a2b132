// The numbers of a run as files: one CSV per replication (one row per iteration) and
// the summary JSON of the whole experiment.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "common/status.h"
#include "experiment_options.h"
#include "iteration_record.h"

namespace relmap::sim {

// A replication whose final thresholded-soft accuracy is below this failed (the
// paper's "runs that end near accuracy 0.5", docs/method.md §7.1).
inline constexpr double kFailedRunAccuracy = 0.6;

// The header of replication-<r>.csv: its columns, in order.
extern const char kIterationCsvHeader[];

// The header and one row per iteration. Undefined scores and absent values (no
// target, no outcome posted, oracle mode's push) are empty fields; labels are 1
// (moveable) or 0.
// The objects the replication's respawns left out, summed over its iterations (one
// object out of ten respawns counts 1).
int ObjectsLeftOut(const ReplicationResult& r);

void WriteIterationCsv(const ReplicationResult& replication, std::ostream& out);

// How the run was carried out, beyond its options.
struct RunFacts {
  std::string server;  // the address used
  bool server_started = false;
  double elapsed_seconds = 0;
};

// The summary: the configuration, the iteration order, per replication its final
// scores (those of the last iteration's map) and counts, mean/min/max of the final
// scores over the replications that ran to the end, the failed runs, and the mean
// iteration time with its breakdown.
std::string SummaryJson(const ExperimentOptions& options, const RunFacts& facts,
                        const std::vector<ReplicationResult>& replications);

// DIR/replication-<r>.csv for every replication and DIR/summary.json.
Status WriteRunFiles(const ExperimentOptions& options, const RunFacts& facts,
                     const std::vector<ReplicationResult>& replications);

}  // namespace relmap::sim
