// The batch upper reference: scripts/bench-learning-reference.py (a random
// forest and an RBF SVM from scikit-learn) on the stream files the benchmark
// wrote, its rows read back in the table's CSV schema.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "learning_bench/table_row.h"

namespace relmap::learning_bench {

struct ReferenceOutcome {
  std::vector<TableRow> rows;
  // "run", or "not run: <why>" (no python3 with sklearn, the script failed).
  std::string status;
};

// Runs `script` on DIR/*.train.csv and DIR/*.test.csv in `streams_dir`, writing
// `out_csv`, with the first python3 that has sklearn. The script's own output goes to standard
// error, so that the benchmark's standard output stays one table.
ReferenceOutcome RunReference(const std::string& script, const std::string& streams_dir,
                              const std::string& out_csv, std::uint64_t seed);

}  // namespace relmap::learning_bench
