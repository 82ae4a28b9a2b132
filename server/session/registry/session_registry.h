// The sessions of one server, by id. Lookups share a lock; creation and deletion
// take it alone. The sessions themselves serialise their own calls.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/status.h"
#include "session/registry/session_restore.h"
#include "session/session.h"

namespace relmap::session {

class SessionRegistry {
 public:
  // With a `store`, sessions are created and deleted there too, and their
  // samples committed there before they are learned; with `decode_settings` as
  // well, stored sessions come back into memory on their first call
  // (session_restore.h).
  explicit SessionRegistry(std::size_t max_sessions, SessionStore* store = nullptr,
                           StoredSettingsDecoder decode_settings = {});

  struct Created {
    std::shared_ptr<Session> session;
    std::string token;  // given to the client once; the registry keeps its hash
  };
  // A new session with a random id and token. RESOURCE_EXHAUSTED at the limit.
  // `config_blob` is what the store keeps to rebuild the settings after a restart.
  StatusOr<Created> Create(SessionSettings settings, std::string config_blob,
                           std::int64_t now_unix_ms);
  // A new session as Create gives, which then learns an exported `state`
  // (Session::ImportState). An import that fails leaves no session behind.
  StatusOr<Created> Import(SessionSettings settings, std::string config_blob,
                           const SessionState& state, std::int64_t now_unix_ms);
  // Loads a session that is in the store but not in memory (NOT_FOUND if the
  // store does not have it either), in place of LoadStoredSession.
  using Loader = std::function<StatusOr<std::shared_ptr<Session>>(const std::string& id)>;
  void set_loader(Loader loader) { loader_ = std::move(loader); }

  // Told the number of sessions in memory each time it changes, in order (it is called
  // under the registry's lock, so it must not call the registry). The server sizes its
  // worker pool and frame queue by it (server/worker_sizing.h).
  using SizeObserver = std::function<void(std::size_t sessions)>;
  void set_size_observer(SizeObserver observer);

  // The sessions in memory now.
  std::vector<std::shared_ptr<Session>> Resident() const;
  // Drops from memory the sessions of a store-backed registry that no call holds
  // and that were last used before `cutoff_unix_ms`; returns their ids. They
  // are loaded again on their next call.
  std::vector<std::string> EvictIdle(std::int64_t cutoff_unix_ms);
  // Deletes, from memory and from the store, the sessions that no call holds and that
  // were last used before `cutoff_unix_ms` (a session that ends; EvictIdle only unloads).
  // A resident session's last use is its last call; an evicted one's, the last call
  // before its eviction; a stored one this registry has not had in memory (after a
  // restart) counts as used at the first call of ExpireIdle that sees it (`now_unix_ms`).
  // With a store that other servers share, only sessions in memory here, held here
  // since their last call, are deleted. Returns the ids of the deleted sessions.
  std::vector<std::string> ExpireIdle(std::int64_t cutoff_unix_ms, std::int64_t now_unix_ms);
  SessionStore* store() const { return store_; }
  // The policy given to every session created or adopted from now on.
  void set_policy(const SessionPolicy& policy) { policy_ = policy; }
  // The session, loaded with the loader if it is not in memory. NOT_FOUND for an
  // unknown id. With a store, every call (re)acquires the session's ownership there:
  // UNAVAILABLE while another server owns it, and a session taken over by another
  // server since this one held it is loaded from the store again.
  StatusOr<std::shared_ptr<Session>> Find(const std::string& id);
  // Gives up the ownership of a session this server created, keeping it in memory:
  // behind a load balancer that routes by session id, CreateSession lands on any
  // server, and the session's calls may then go to another one, which must be able
  // to take it at once. When the session's next call comes here, it is loaded anew
  // if another server has had it meanwhile.
  void HandOver(const std::string& id) {
    if (store_ != nullptr) store_->ReleaseOwnership(id);
  }
  // Drops every session from memory and gives up their ownership in the store, so
  // that other servers can take them over at once (a server that stops). No-op
  // without a store: memory is then the only copy.
  void ReleaseAll();
  // A session as a listing shows it.
  struct Listed {
    std::string id;
    SessionSettings settings;
    SessionStats stats;
  };
  // Up to `limit` sessions with ids after `after_id` (all when empty), ordered by id;
  // `more` tells whether further sessions follow. A session in memory is shown as it is
  // there, unless the store is shared (another server may have moved on from the copy
  // here); one that is not, or with a shared store, from its summary in the store
  // (SessionSummary), without loading it. Only a session whose summary does not cover its stored
  // samples (stored before summaries, or its last summary lost in a crash) is read from the store,
  // for the page only and not kept, so that listing a large store does not pull every
  // session into memory nor take sessions other servers serve.
  struct Page {
    std::vector<Listed> sessions;
    bool more = false;
  };
  Page List(const std::string& after_id, std::size_t limit);
  // NOT_FOUND for an unknown id.
  Status Delete(const std::string& id);

 private:
  // The session as it is in memory, or a copy read from the store for a moment
  // (not owned, not kept); NOT_FOUND for an unknown id.
  StatusOr<std::shared_ptr<Session>> Peek(const std::string& id);
  static Status OwnershipError(const std::string& id, const Status& status);
  static Listed ListedOf(const Session& session);
  // The session as its stored summary shows it, or nullopt when the summary does not
  // cover every stored sample or the settings do not decode.
  std::optional<Listed> ListedOf(const SessionSummary& summary) const;
  // Records the summaries of sessions leaving memory, then gives up their ownership.
  void Unload(const std::vector<std::shared_ptr<Session>>& sessions);
  // Tells the size observer, with mutex_ held.
  void SizeChanged() const;

  const std::size_t max_sessions_;
  SessionStore* const store_;
  SessionPolicy policy_;
  StoredSettingsDecoder decode_settings_;
  Loader loader_;
  SizeObserver size_observer_;  // guarded by mutex_
  std::mutex load_mutex_;       // one load at a time, so an id is never loaded twice
  mutable std::shared_mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<Session>> sessions_;
  // Last use of the stored sessions not in memory that ExpireIdle has seen (unix ms).
  std::unordered_map<std::string, std::int64_t> stored_last_used_;
};

}  // namespace relmap::session
