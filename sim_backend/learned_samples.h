// What a physical-mode replication taught its session, sample by sample: the feature
// the server learned for each pushed target, the label its change detector gave it,
// and the simulator's ground truth beside it. The real-like streams of
// relmap-bench-learning (`relmap-sim dataset --mode physical`).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/status.h"
#include "iteration_record.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::sim {

struct LearnedSample {
  int iteration = 0;             // of the replication, 1-based
  std::uint32_t target = 0;      // the pushed supervoxel of that iteration's frame
  bool label = false;            // what the session learned (PostOutcomeResponse.label)
  bool truth = false;            // the target's ground truth (ground_truth.h)
  std::vector<double> features;  // as the session stored them
};

// Pairs the samples of `state` (ExportSession: every sample in learning order) with
// the iterations of `iterations` that learned one (IterationRecord::label set), in
// order. FAILED_PRECONDITION when they do not pair one to one: another count (a
// session that learned more than each push's target, `--labels object`) or a sample
// whose label is not its iteration's.
StatusOr<std::vector<LearnedSample>> PairLearnedSamples(
    const std::vector<IterationRecord>& iterations, const v1::SessionState& state);

// `csv_path`: relmap-cmm's CSV (a header "label,f1,...,fp", then per sample the
// learned label and its features, as common/labelled_csv.h writes them).
// `truth_csv_path`, unless empty: the same rows with the ground truth as the label.
// `iterations_path`: a header "iteration,target,label,truth", then per row of the
// CSV, in the same order, where it came from. INTERNAL naming the file when one
// cannot be written.
Status WriteLearnedSamples(const std::vector<LearnedSample>& samples, const std::string& csv_path,
                           const std::string& truth_csv_path, const std::string& iterations_path);

}  // namespace relmap::sim
