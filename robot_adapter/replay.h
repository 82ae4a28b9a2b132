// relmap-robot replay: a recorded run against a server, without a robot. Each posted
// iteration's before cloud is uploaded again to a new session with the recorded
// session config, and its recorded label posted for its recorded target, so the new
// session learns the same samples. Where the run recorded ground truth, the accuracy
// of every map gives the learning curve.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/status.h"
#include "relevance_client.h"

namespace relmap::robot {

struct ReplayedIteration {
  int iteration = 0;
  std::uint32_t supervoxel = 0;
  v1::Label label = v1::LABEL_UNSPECIFIED;
  // The soft accuracy of the map computed before learning this iteration's label.
  std::optional<double> accuracy;
};

struct ReplayResult {
  client::SessionHandle session;
  std::vector<ReplayedIteration> iterations;
};

// FAILED_PRECONDITION when the replayed maps do not have the recorded supervoxels
// (another server version or config segments differently): the labels would not
// mean the same.
StatusOr<ReplayResult> ReplayRun(const std::string& run_dir, client::RelevanceClient& client);

}  // namespace relmap::robot
