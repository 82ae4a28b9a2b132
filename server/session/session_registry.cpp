// Creation, lookup and deletion of sessions.
#include "session/session_registry.h"

#include <algorithm>
#include <chrono>
#include <mutex>

#include "session/credentials.h"

namespace relmap::session {

StatusOr<SessionRegistry::Created> SessionRegistry::Create(SessionSettings settings,
                                                           std::string config_blob,
                                                           std::int64_t now_unix_ms) {
  std::string token = RandomHex(32);
  auto session =
      Session::Create(RandomHex(16), Sha256Hex(token), std::move(settings), now_unix_ms, store_);
  if (!session.ok()) return session.status();
  std::shared_ptr<Session> shared = std::move(session).value();
  shared->set_snapshot_every(snapshot_every_);
  std::unique_lock lock(mutex_);
  if (sessions_.size() >= max_sessions_) {
    return ResourceExhaustedError("the server holds its maximum of " +
                                  std::to_string(max_sessions_) + " sessions");
  }
  if (store_ != nullptr) {
    SessionRecord record;
    record.id = shared->id();
    record.token_hash = shared->token_hash();
    record.created_at = Timestamp(std::chrono::milliseconds(now_unix_ms));
    record.config = std::move(config_blob);
    record.cmm_config = shared->settings().classifier;
    record.feature_dimension = shared->settings().feature_dimension;
    if (Status status = store_->CreateSession(record); !status.ok()) return status;
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

Status SessionRegistry::Adopt(std::shared_ptr<Session> session) {
  session->set_snapshot_every(snapshot_every_);
  std::unique_lock lock(mutex_);
  if (!sessions_.emplace(session->id(), session).second) {
    return Status(StatusCode::kAlreadyExists, "session '" + session->id() + "' exists twice");
  }
  return OkStatus();
}

Status SessionRegistry::Delete(const std::string& id) {
  std::unique_lock lock(mutex_);
  if (sessions_.find(id) == sessions_.end()) return NotFoundError("no session '" + id + "'");
  if (store_ != nullptr) {
    if (Status status = store_->DeleteSession(id); !status.ok()) return status;
  }
  sessions_.erase(id);
  return OkStatus();
}

}  // namespace relmap::session
