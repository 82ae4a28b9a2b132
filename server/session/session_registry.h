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
  // With a `store`, sessions are created and deleted there too, and their
  // samples committed there before they are learned.
  explicit SessionRegistry(std::size_t max_sessions, SessionStore* store = nullptr)
      : max_sessions_(max_sessions), store_(store) {}

  struct Created {
    std::shared_ptr<Session> session;
    std::string token;  // given to the client once; the registry keeps its hash
  };
  // A new session with a random id and token. RESOURCE_EXHAUSTED at the limit.
  // `config_blob` is what the store keeps to rebuild the settings after a restart.
  StatusOr<Created> Create(SessionSettings settings, std::string config_blob,
                           std::int64_t now_unix_ms);
  // Adds a session rebuilt from the store at start-up.
  Status Adopt(std::shared_ptr<Session> session);
  SessionStore* store() const { return store_; }
  // Snapshot policy given to every session created or adopted from now on.
  void set_snapshot_every(std::size_t samples) { snapshot_every_ = samples; }
  // NOT_FOUND for an unknown id.
  StatusOr<std::shared_ptr<Session>> Find(const std::string& id) const;
  // Every session, ordered by id.
  std::vector<std::shared_ptr<Session>> List() const;
  // NOT_FOUND for an unknown id.
  Status Delete(const std::string& id);

 private:
  const std::size_t max_sessions_;
  SessionStore* const store_;
  std::size_t snapshot_every_ = 0;
  mutable std::shared_mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<Session>> sessions_;
};

}  // namespace relmap::session
