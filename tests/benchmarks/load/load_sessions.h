// Creating and deleting the sessions of a load run.
#pragma once

#include <string>
#include <vector>

#include "common/random.h"
#include "common/status.h"
#include "load_driver.h"
#include "relevance_client.h"

namespace relmap::load {

// `count` sessions with default settings, their seeds the next words of `seeds`: the same
// seed stream creates the same sessions. On a failure, the ones created are deleted again.
StatusOr<std::vector<LoadSession>> CreateLoadSessions(client::RelevanceClient& client, int count,
                                                      Random& seeds);

// Deletes every session of `sessions` that has an id; a failure is printed, not fatal.
void DeleteLoadSessions(client::RelevanceClient& client, const std::vector<LoadSession>& sessions);

}  // namespace relmap::load
