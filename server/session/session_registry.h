// The sessions of one server, by id. Lookups share a lock; creation and deletion
// take it alone. The sessions themselves serialise their own calls.
#pragma once

#include <memory>
#include <shared_mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/status.h"
#include "session/session.h"

namespace relmap::session {

class SessionRegistry {
 public:
  explicit SessionRegistry(std::size_t max_sessions) : max_sessions_(max_sessions) {}

  struct Created {
    std::shared_ptr<Session> session;
    std::string token;  // given to the client once; the registry keeps its hash
  };
  // A new session with a random id and token. RESOURCE_EXHAUSTED at the limit.
  StatusOr<Created> Create(SessionSettings settings, std::int64_t now_unix_ms);
  // NOT_FOUND for an unknown id.
  StatusOr<std::shared_ptr<Session>> Find(const std::string& id) const;
  // Every session, ordered by id.
  std::vector<std::shared_ptr<Session>> List() const;
  // NOT_FOUND for an unknown id.
  Status Delete(const std::string& id);

 private:
  const std::size_t max_sessions_;
  mutable std::shared_mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<Session>> sessions_;
};

}  // namespace relmap::session
