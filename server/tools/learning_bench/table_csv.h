// The table as CSV: the schema that relmap-bench-learning writes and that
// scripts/bench-learning-reference.py writes too, so that its rows merge in.
#pragma once

#include <string>
#include <vector>

#include "common/status.h"
#include "learning_bench/table_row.h"

namespace relmap::learning_bench {

// stream,learner,replications,balanced_accuracy_mean,balanced_accuracy_min,
// soft_accuracy,log_loss,brier,components,update_p50_us,update_p99_us,predict_us
// An undefined value is an empty cell; components is "c0+c1".
std::string TableCsv(const std::vector<TableRow>& rows);

// Rows of a file in that schema (columns in any order, all present). A missing
// column, a ragged row or a cell that is not a number → INVALID_ARGUMENT naming
// the file and line; an unreadable file → NOT_FOUND.
StatusOr<std::vector<TableRow>> ReadTableCsv(const std::string& path);

}  // namespace relmap::learning_bench
