// A stored session back in memory: the settings from its stored SessionConfig,
// the model from its latest snapshot plus the samples after it (the same model,
// bit for bit, as before the restart or eviction).
#pragma once

#include <memory>
#include <string>

#include "common/status.h"
#include "session/session.h"
#include "session/session_store.h"

namespace relmap::service {

// NOT_FOUND for an id the store does not hold; DATA_LOSS when its record,
// snapshot or samples do not decode.
StatusOr<std::shared_ptr<session::Session>> LoadStoredSession(session::SessionStore& store,
                                                              const std::string& id);

}  // namespace relmap::service
