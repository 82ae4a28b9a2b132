// The shared session store: PostgreSQL through libpq, so that several servers
// serve the same sessions, each session written by one server at a time.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"
#include "session/store/session_store.h"

namespace relmap::session {

class PgConnection;
class PostgresConnectionPool;

struct PostgresStoreOptions {
  // How long a server's hold on a session lasts without being renewed. Every
  // AcquireOwnership and every write renews it; once it has run out, another
  // server may take the session over even while this one is still connected (a
  // server that hangs). A server that is no longer connected loses its sessions
  // at once, whatever is left of the lease.
  std::chrono::milliseconds lease_ttl{30'000};
  // Connections kept open to the database; a call beyond that many waits for one.
  int max_connections = 4;
  // How long opening a connection may take before the call fails with UNAVAILABLE.
  std::chrono::seconds connect_timeout{5};
  // How long a call waits for a session's owner row while another server's call
  // holds it, before failing with UNAVAILABLE; also how long PostgreSQL keeps a
  // transaction open whose server stopped talking mid-way (it is then ended and
  // its locks freed). The store's own transactions last milliseconds.
  std::chrono::milliseconds lock_timeout{10'000};
  // This store's name as an owner of sessions, also the application_name of its
  // connections (which is how other servers see that it is alive): at most 63
  // printable ASCII characters, unique among the servers sharing the database.
  // Empty: relmap-<hostname>-<pid>-<random>.
  std::string owner_id;
};

// Thread-safe through a pool of connections; each operation is one transaction
// on one connection, and a write returns once PostgreSQL has committed it
// (synchronous_commit is never off on the store's connections).
//
// Ownership: a session is written only by the store instance that owns it
// (CreateSession, or AcquireOwnership). The database arbitrates, with a
// session_owners row per session (owner, epoch, lease expiry by the database's
// clock); every write checks, in its own transaction, that the row still names
// this instance with the epoch it took, and is ABORTED otherwise, storing
// nothing. A write to a session this instance does not own is ABORTED too.
// Destroying the store releases every session it owns.
class PostgresSessionStore final : public SessionStore {
 public:
  // Connects to `conninfo` (a postgres:// URI or a "key=value ..." string; any
  // application_name in it is replaced by the owner id) and creates or migrates
  // the schema; several servers may open the same database at once. The
  // database unreachable → UNAVAILABLE; a schema newer than this build →
  // FAILED_PRECONDITION; bad options → INVALID_ARGUMENT.
  static StatusOr<std::unique_ptr<PostgresSessionStore>> Open(
      const std::string& conninfo, const PostgresStoreOptions& options = {});
  ~PostgresSessionStore() override;
  PostgresSessionStore(const PostgresSessionStore&) = delete;
  PostgresSessionStore& operator=(const PostgresSessionStore&) = delete;

  // The name under which this instance owns sessions.
  const std::string& owner_id() const { return owner_id_; }

  // CreateSession also makes this instance the session's owner.
  Status CreateSession(const SessionRecord& record) override;
  StatusOr<SessionRecord> LoadSession(std::string_view id) override;
  StatusOr<std::vector<SessionSummary>> ListSessions() override;
  Status DeleteSession(std::string_view id) override;
  StatusOr<std::int64_t> AppendSample(std::string_view session_id, std::string_view request_id,
                                      std::span<const double> features, int label) override;
  StatusOr<std::vector<StoredSample>> LoadSamples(std::string_view session_id) override;
  Status SaveSnapshot(std::string_view session_id, const cmm::CmmSnapshot& snapshot,
                      std::int64_t sample_count) override;
  StatusOr<std::optional<StoredSnapshot>> LoadLatestSnapshot(std::string_view session_id) override;
  Status IncrementCounters(std::string_view session_id, const SessionCounters& delta) override;
  Status RecordModelSummary(std::string_view session_id, const ModelSummary& summary) override;

  // Takes the session when it has no owner, its owner's lease has run out or its
  // owner has no connection to the database any more (a server killed with
  // kill -9: PostgreSQL drops its connections); otherwise UNAVAILABLE naming the
  // owner and its lease.
  StatusOr<Ownership> AcquireOwnership(std::string_view session_id) override;
  void ReleaseOwnership(std::string_view session_id) override;
  bool shared() const override { return true; }

 private:
  PostgresSessionStore(std::unique_ptr<PostgresConnectionPool> pool,
                       const PostgresStoreOptions& options);

  // Runs `body` in one transaction on a pooled connection, committed if `body`
  // returns OK and rolled back otherwise.
  Status InTransaction(const std::function<Status(PgConnection&)>& body);
  // Runs `body` in one transaction that first fences the write on `session_id`
  // (checks that this instance still owns it under its epoch, renews the lease
  // and locks the owner row), and commits if `body` returns OK. `body` gets the
  // session's feature dimension.
  Status FencedWrite(std::string_view session_id,
                     const std::function<Status(PgConnection&, int dimension)>& body);

  // The epoch under which this instance owns `session_id`, if it does.
  std::optional<std::int64_t> HeldEpoch(std::string_view session_id);
  void Remember(std::string_view session_id, std::optional<std::int64_t> epoch);

  std::unique_ptr<PostgresConnectionPool> pool_;
  const std::string owner_id_;
  const std::chrono::milliseconds lease_ttl_;

  std::mutex epochs_mutex_;
  std::map<std::string, std::int64_t, std::less<>> epochs_;  // guarded by epochs_mutex_
};

}  // namespace relmap::session
