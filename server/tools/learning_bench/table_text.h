// The side-by-side table as the benchmark prints it, and the best learner of
// each stream.
#pragma once

#include <string>
#include <vector>

#include "learning_bench/summary.h"
#include "learning_bench/table_row.h"

namespace relmap::learning_bench {

// Fixed-width columns, one line per row, "-" for an undefined value.
std::string FormatTable(const std::vector<TableRow>& rows);

// "best on <stream>: <learner> (balanced accuracy 0.912)", one line per
// stream, naming the batch reference when it scores higher.
std::string FormatBestLines(const std::vector<StreamBest>& best);

}  // namespace relmap::learning_bench
