// A page token is the id of the page's last session: ids are listed in order, so the
// next page starts after it whatever was created or deleted in between.
#include "session/registry/session_listing.h"

namespace relmap::session {

StatusOr<SessionPage> ListSessionPage(SessionRegistry& registry, const std::string& page_token,
                                      std::uint32_t page_size) {
  if (page_size > kMaxSessionPageSize) {
    return InvalidArgumentError("page_size is at most " + std::to_string(kMaxSessionPageSize) +
                                ", got " + std::to_string(page_size));
  }
  SessionRegistry::Page listed =
      registry.List(page_token, page_size == 0 ? kDefaultSessionPageSize : page_size);
  SessionPage page;
  if (listed.more) page.next_page_token = listed.sessions.back().id;
  page.sessions = std::move(listed.sessions);
  return page;
}

}  // namespace relmap::session
