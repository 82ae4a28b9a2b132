// Creation, lookup and deletion of sessions.
#include "session/registry/session_registry.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>
#include <unordered_set>

#include "session/credentials.h"
#include "session/registry/memory_release.h"

namespace relmap::session {

SessionRegistry::SessionRegistry(std::size_t max_sessions, SessionStore* store,
                                 StoredSettingsDecoder decode_settings)
    : max_sessions_(max_sessions), store_(store), decode_settings_(std::move(decode_settings)) {
  if (store_ != nullptr && decode_settings_) {
    loader_ = [store, decode = decode_settings_](const std::string& id) {
      return LoadStoredSession(*store, id, decode);
    };
  }
}

StatusOr<SessionRegistry::Created> SessionRegistry::Create(SessionSettings settings,
                                                           std::string config_blob,
                                                           std::int64_t now_unix_ms) {
  std::string token = RandomHex(32);
  auto session = Session::Create(RandomHex(16), Sha256Hex(token), settings, now_unix_ms, store_);
  if (!session.ok()) return session.status();
  std::shared_ptr<Session> shared = std::move(session).value();
  shared->set_policy(policy_);
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
  SizeChanged();
  lock.unlock();
  shared->RecordSummary();  // so that a listing need not load it before its first sample
  return Created{std::move(shared), std::move(token)};
}

StatusOr<SessionRegistry::Created> SessionRegistry::Import(SessionSettings settings,
                                                           std::string config_blob,
                                                           const SessionState& state,
                                                           std::int64_t now_unix_ms) {
  auto created = Create(settings, std::move(config_blob), now_unix_ms);
  if (!created.ok()) return created.status();
  if (auto imported = created->session->ImportState(state, now_unix_ms); !imported.ok()) {
    (void)Delete(created->session->id());
    return imported.status();
  }
  return created;
}

StatusOr<std::shared_ptr<Session>> SessionRegistry::Find(const std::string& id) {
  const auto resident = [&]() -> std::shared_ptr<Session> {
    std::shared_lock lock(mutex_);
    const auto it = sessions_.find(id);
    return it == sessions_.end() ? nullptr : it->second;
  };
  const auto forget = [&] {
    std::unique_lock lock(mutex_);
    sessions_.erase(id);
    SizeChanged();
  };
  if (auto session = resident()) {
    if (store_ == nullptr) return session;
    // A shared store may have let another server take the session over since this
    // one last touched it: then the copy in memory is stale and is loaded anew.
    auto ownership = store_->AcquireOwnership(id);
    if (ownership.ok() && ownership->held_throughout) return session;
    forget();
    if (!ownership.ok()) return OwnershipError(id, ownership.status());
  }
  if (!loader_) return NotFoundError("no session '" + id + "'");
  std::lock_guard load(load_mutex_);
  if (auto session = resident()) return session;  // loaded by another call meanwhile
  if (store_ != nullptr) {
    // Owned before it is read, so that no other server appends while it loads.
    if (auto ownership = store_->AcquireOwnership(id); !ownership.ok()) {
      return OwnershipError(id, ownership.status());
    }
  }
  auto loaded = loader_(id);
  if (!loaded.ok()) {
    if (loaded.status().code() == StatusCode::kNotFound)
      return NotFoundError("no session '" + id + "'");
    return loaded.status();
  }
  (*loaded)->set_policy(policy_);
  std::unique_lock lock(mutex_);
  sessions_.emplace(id, *loaded);
  SizeChanged();
  stored_last_used_.erase(id);
  return loaded;
}

StatusOr<std::shared_ptr<Session>> SessionRegistry::Peek(const std::string& id) {
  {
    std::shared_lock lock(mutex_);
    if (const auto it = sessions_.find(id); it != sessions_.end()) return it->second;
  }
  if (!loader_) return NotFoundError("no session '" + id + "'");
  // Read, not owned, and not kept: listing must neither take sessions that other
  // servers serve nor pull a large store into memory.
  auto loaded = loader_(id);
  if (!loaded.ok()) return loaded.status();
  (*loaded)->set_policy(policy_);
  return loaded;
}

Status SessionRegistry::OwnershipError(const std::string& id, const Status& status) {
  if (status.code() == StatusCode::kNotFound) return NotFoundError("no session '" + id + "'");
  return status;
}

std::vector<std::shared_ptr<Session>> SessionRegistry::Resident() const {
  std::vector<std::shared_ptr<Session>> out;
  std::shared_lock lock(mutex_);
  for (const auto& [id, session] : sessions_) out.push_back(session);
  return out;
}

SessionRegistry::Listed SessionRegistry::ListedOf(const Session& session) {
  return {session.id(), session.settings(), session.Stats()};
}

std::optional<SessionRegistry::Listed> SessionRegistry::ListedOf(
    const SessionSummary& summary) const {
  if (!decode_settings_ || !summary.model_current()) return std::nullopt;
  auto settings = StoredSessionSettings(summary.record, decode_settings_);
  if (!settings.ok()) return std::nullopt;
  Listed listed{summary.record.id, std::move(settings).value(), {}};
  SessionStats& stats = listed.stats;
  for (int label = 0; label < 2; ++label) {
    stats.samples[label] = static_cast<std::uint64_t>(summary.samples[label]);
    stats.components[label] = static_cast<std::uint32_t>(summary.model->components[label]);
  }
  stats.frames = static_cast<std::uint64_t>(summary.record.counters.frames_computed);
  stats.created_unix_ms = UnixMilliseconds(summary.record.created_at);
  stats.last_used_unix_ms = UnixMilliseconds(summary.model->last_used);
  return listed;
}

SessionRegistry::Page SessionRegistry::List(const std::string& after_id, std::size_t limit) {
  std::vector<SessionSummary> stored;
  if (store_ != nullptr && loader_) {
    if (auto listed = store_->ListSessions(); listed.ok()) stored = std::move(listed).value();
  }
  if (stored.empty()) {
    for (const auto& session : Resident()) stored.emplace_back().record.id = session->id();
  }
  const auto by_id = [](const SessionSummary& a, const SessionSummary& b) {
    return a.record.id < b.record.id;
  };
  std::sort(stored.begin(), stored.end(), by_id);
  SessionSummary after;
  after.record.id = after_id;
  // With a store of its own the server's copy is the session; with a shared one the
  // copy may be one another server has moved on from (a session created here and
  // served there), and the store's summary is what every server agrees on.
  const bool shared = store_ != nullptr && store_->shared();
  Page page;
  for (auto it = std::upper_bound(stored.begin(), stored.end(), after, by_id); it != stored.end();
       ++it) {
    if (page.sessions.size() == limit) {
      page.more = true;
      break;
    }
    const std::string& id = it->record.id;
    std::shared_ptr<Session> resident;
    {
      std::shared_lock lock(mutex_);
      if (const auto found = sessions_.find(id); found != sessions_.end()) resident = found->second;
    }
    if (resident != nullptr && !shared) {
      page.sessions.push_back(ListedOf(*resident));
      continue;
    }
    if (auto summarised = ListedOf(*it)) {
      page.sessions.push_back(std::move(summarised).value());
      continue;
    }
    if (resident != nullptr) {  // a summary behind its samples: between a call's two writes
      page.sessions.push_back(ListedOf(*resident));
      continue;
    }
    spdlog::info("listing session={}: its stored summary does not cover its {} samples; loading it",
                 id, it->sample_count());
    // A session deleted since the ids were read is skipped.
    if (auto session = Peek(id); session.ok()) page.sessions.push_back(ListedOf(**session));
  }
  return page;
}

std::vector<std::string> SessionRegistry::EvictIdle(std::int64_t cutoff_unix_ms) {
  std::vector<std::string> evicted;
  if (store_ == nullptr) return evicted;  // memory is the only copy
  std::vector<std::shared_ptr<Session>> unloaded;
  std::unique_lock lock(mutex_);
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    // use_count 1: only the registry holds it, no call is running on it.
    const std::int64_t last_used = it->second->Stats().last_used_unix_ms;
    if (it->second.use_count() == 1 && last_used < cutoff_unix_ms) {
      evicted.push_back(it->first);
      if (!store_->shared()) stored_last_used_[it->first] = last_used;  // for ExpireIdle
      unloaded.push_back(std::move(it->second));
      it = sessions_.erase(it);
    } else {
      ++it;
    }
  }
  SizeChanged();
  lock.unlock();
  Unload(unloaded);
  unloaded.clear();
  if (!evicted.empty()) ReturnFreedMemory();
  return evicted;
}

void SessionRegistry::Unload(const std::vector<std::shared_ptr<Session>>& sessions) {
  for (const auto& session : sessions) {
    // Its last call, which only memory knew, for listings while it is out.
    session->RecordSummary();
    // Another server may take it at once rather than after its hold expires.
    store_->ReleaseOwnership(session->id());
  }
}

std::vector<std::string> SessionRegistry::ExpireIdle(std::int64_t cutoff_unix_ms,
                                                     std::int64_t now_unix_ms) {
  std::vector<std::string> expired;
  // Only sessions in memory here when other servers share the store: the last use of
  // the others is theirs to know, and a lease that ran out says nothing of it.
  std::optional<std::unordered_set<std::string>> stored_ids;
  if (store_ != nullptr && !store_->shared()) {
    if (auto stored = store_->ListSessions(); stored.ok()) {
      stored_ids.emplace();
      for (const SessionSummary& summary : *stored) stored_ids->insert(summary.record.id);
    }
  }
  // Owned before it is deleted: a session in memory here that another server has served
  // since is not idle.
  const auto owned_here = [&](const std::string& id) {
    if (store_ == nullptr) return true;
    auto ownership = store_->AcquireOwnership(id);
    return ownership.ok() && ownership->held_throughout;
  };
  const auto deleted = [&](const std::string& id) {
    return store_ == nullptr || store_->DeleteSession(id).ok();
  };
  std::unique_lock lock(mutex_);
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    // use_count 1: only the registry holds it, no call is running on it.
    if (it->second.use_count() == 1 && it->second->Stats().last_used_unix_ms < cutoff_unix_ms &&
        owned_here(it->first) && deleted(it->first)) {
      expired.push_back(it->first);
      it = sessions_.erase(it);
    } else {
      ++it;
    }
  }
  SizeChanged();
  if (!expired.empty()) ReturnFreedMemory();
  if (!stored_ids) return expired;
  // Forget the ids the store no longer has (deleted by a call or by another server).
  std::erase_if(stored_last_used_,
                [&](const auto& entry) { return stored_ids->count(entry.first) == 0; });
  for (const std::string& id : *stored_ids) {
    if (sessions_.count(id) != 0) continue;
    const auto [it, first_seen] = stored_last_used_.try_emplace(id, now_unix_ms);
    if (first_seen || it->second >= cutoff_unix_ms) continue;
    if (deleted(id)) {
      expired.push_back(id);
      stored_last_used_.erase(it);
    }
  }
  return expired;
}

void SessionRegistry::set_size_observer(SizeObserver observer) {
  std::unique_lock lock(mutex_);
  size_observer_ = std::move(observer);
  SizeChanged();
}

void SessionRegistry::SizeChanged() const {
  if (size_observer_) size_observer_(sessions_.size());
}

void SessionRegistry::ReleaseAll() {
  std::unique_lock lock(mutex_);
  if (store_ == nullptr) return;  // memory is the only copy: nothing to hand over
  std::vector<std::shared_ptr<Session>> released;
  for (auto& [id, session] : sessions_) released.push_back(std::move(session));
  sessions_.clear();
  SizeChanged();
  lock.unlock();
  Unload(released);
}

Status SessionRegistry::Delete(const std::string& id) {
  std::unique_lock lock(mutex_);
  if (store_ != nullptr) {
    // The store knows evicted sessions too.
    if (Status status = store_->DeleteSession(id); !status.ok()) return status;
  } else if (sessions_.find(id) == sessions_.end()) {
    return NotFoundError("no session '" + id + "'");
  }
  // Freed outside the lock, unless a call still holds the session (it goes with that call).
  std::shared_ptr<Session> deleted;
  if (const auto it = sessions_.find(id); it != sessions_.end()) {
    deleted = std::move(it->second);
    sessions_.erase(it);
  }
  SizeChanged();
  stored_last_used_.erase(id);
  lock.unlock();
  deleted.reset();
  ReturnFreedMemory();
  return OkStatus();
}

}  // namespace relmap::session
