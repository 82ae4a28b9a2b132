// Creation, lookup and deletion of sessions.
#include "session/session_registry.h"

#include <algorithm>
#include <mutex>

#include "session/credentials.h"

namespace relmap::session {

StatusOr<SessionRegistry::Created> SessionRegistry::Create(SessionSettings settings,
                                                           std::int64_t now_unix_ms) {
  std::string token = RandomHex(32);
  auto session = Session::Create(RandomHex(16), Sha256Hex(token), std::move(settings), now_unix_ms);
  if (!session.ok()) return session.status();
  std::shared_ptr<Session> shared = std::move(session).value();
  std::unique_lock lock(mutex_);
  if (sessions_.size() >= max_sessions_) {
    return ResourceExhaustedError("the server holds its maximum of " +
                                  std::to_string(max_sessions_) + " sessions");
  }
  sessions_.emplace(shared->id(), shared);
  return Created{std::move(shared), std::move(token)};
}

StatusOr<std::shared_ptr<Session>> SessionRegistry::Find(const std::string& id) const {
  std::shared_lock lock(mutex_);
  const auto it = sessions_.find(id);
  if (it == sessions_.end()) return NotFoundError("no session '" + id + "'");
  return it->second;
}

std::vector<std::shared_ptr<Session>> SessionRegistry::List() const {
  std::vector<std::shared_ptr<Session>> out;
  {
    std::shared_lock lock(mutex_);
    for (const auto& [id, session] : sessions_) out.push_back(session);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a->id() < b->id(); });
  return out;
}

Status SessionRegistry::Delete(const std::string& id) {
  std::unique_lock lock(mutex_);
  if (sessions_.erase(id) == 0) return NotFoundError("no session '" + id + "'");
  return OkStatus();
}

}  // namespace relmap::session
