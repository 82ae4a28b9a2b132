// The learning curves of a run as PNG line plots, as in the paper's figures: per
// iteration the mean over replications with the min–max envelope.
#pragma once

#include <vector>

#include "common/status.h"
#include "iteration_record.h"

namespace relmap::sim {

// DIR/accuracy.png, precision.png, recall.png (the thresholded-soft metric, with
// the soft metric as a second series), samples.png and components.png (per class).
Status WriteCurvePlots(const std::vector<ReplicationResult>& replications,
                       const std::string& directory);

}  // namespace relmap::sim
