// Start-up: every session of the store back in the registry, its model rebuilt
// by relearning its samples in order (deterministic: the same model, bit for bit).
#pragma once

#include "common/status.h"
#include "session/session_registry.h"
#include "session/session_store.h"

namespace relmap::service {

// Restores every stored session into `registry`. A session whose record or
// samples do not decode → DATA_LOSS naming it (the server refuses to start
// rather than serve a session without its acknowledged samples).
Status RestoreSessions(session::SessionStore& store, session::SessionRegistry& registry);

}  // namespace relmap::service
