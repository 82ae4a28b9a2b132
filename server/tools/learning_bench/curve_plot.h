// Learning curves of one stream as a PNG: held-out balanced accuracy against
// training samples, one line per learner with its min–max envelope over the
// replications.
#pragma once

#include <string>
#include <vector>

#include "common/status.h"
#include "learning_bench/summary.h"

namespace relmap::learning_bench {

// Draws the curves of `stream` among `curves` into `path`.
Status WriteCurvePng(const std::string& stream, const std::vector<CurveSummary>& curves,
                     const std::string& path);

// Every curve point as CSV: stream,learner,samples,mean,min,max.
std::string CurvesCsv(const std::vector<CurveSummary>& curves);

}  // namespace relmap::learning_bench
