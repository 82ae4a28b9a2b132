// ListSessions' pages over the registry: a page size within bounds, and the token
// that names the page after.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/status.h"
#include "session/registry/session_registry.h"

namespace relmap::session {

inline constexpr std::uint32_t kDefaultSessionPageSize = 100;
inline constexpr std::uint32_t kMaxSessionPageSize = 1000;

struct SessionPage {
  std::vector<SessionRegistry::Listed> sessions;  // ordered by id
  std::string next_page_token;                    // empty on the last page
};

// The sessions after `page_token` (from the start when empty), `page_size` of them
// (0: kDefaultSessionPageSize). More than kMaxSessionPageSize → INVALID_ARGUMENT.
StatusOr<SessionPage> ListSessionPage(SessionRegistry& registry, const std::string& page_token,
                                      std::uint32_t page_size);

}  // namespace relmap::session
