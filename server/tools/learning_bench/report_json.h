// The benchmark's whole result as one JSON document: the run's settings, the
// table, the best learner per stream and the learning curves.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "learning_bench/summary.h"
#include "learning_bench/table_row.h"

namespace relmap::learning_bench {

struct RunSettings {
  std::uint64_t seed = 0;
  int replications = 0;
  int train_samples = 0;
  int test_samples = 0;
  int curve_every = 0;
  std::string reference;  // "run", or "not run: <why>"
  double wall_seconds = 0.0;
};

// Undefined values are null.
std::string ReportJson(const RunSettings& settings, const std::vector<TableRow>& rows,
                       const std::vector<StreamBest>& best,
                       const std::vector<CurveSummary>& curves);

}  // namespace relmap::learning_bench
