// The session store named by relmap-server's --store setting.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <string_view>

#include "common/status.h"
#include "session/store/session_store.h"

namespace relmap::server {

// Opens "sqlite:PATH" (creating PATH's directory) or a "postgres://…" /
// "postgresql://…" URI, whose sessions this server holds for `lease` past its last
// call on them. Anything else → INVALID_ARGUMENT; a store that cannot be opened
// keeps its own status (UNAVAILABLE, DATA_LOSS, FAILED_PRECONDITION).
StatusOr<std::unique_ptr<session::SessionStore>> OpenSessionStore(const std::string& spec,
                                                                  std::chrono::seconds lease);

// Whether `spec` has the form of a store OpenSessionStore opens: "sqlite:…",
// "postgres://…" or "postgresql://…".
bool IsStoreSpec(std::string_view spec);

// The store named without its credentials, for logs: "sqlite:/var/lib/relmap/relmap.sqlite",
// "postgres://db:5432/relmap".
std::string StoreForLogs(const std::string& spec);

}  // namespace relmap::server
