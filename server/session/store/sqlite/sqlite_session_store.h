// The embedded session store: one SQLite file in WAL mode, one connection, every
// acknowledged write on stable storage before the call returns.
#pragma once

#include <chrono>
#include <cstdint>
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

struct SqliteStoreOptions {
  // FULL fsyncs the write-ahead log at every commit, so an acknowledged append
  // survives kill -9 and power loss. NORMAL (WAL) syncs only at checkpoints: it
  // survives kill -9 but may lose the last commits on power loss. NORMAL is for
  // benchmarks and throwaway databases.
  enum class Synchronous { kFull, kNormal };
  Synchronous synchronous = Synchronous::kFull;
  // How long a statement waits for a lock held by another process before
  // failing with UNAVAILABLE.
  std::chrono::milliseconds busy_timeout{5000};
  // Claims the file for this store alone (a lock on PATH.lock): a second exclusive
  // Open of the same file, in any process, is FAILED_PRECONDITION until this store
  // closes or its process dies. A server sets it, so that two servers never share
  // one file, which this store's ownership (every session its own) assumes.
  bool exclusive = false;
};

// Thread-safe through one mutex around one connection. SQLite admits one
// writer per database at a time whatever the connection count, and every write
// here ends in an fsync, so a connection pool would add lock contention
// (SQLITE_BUSY between our own connections) without adding write throughput;
// reads are short and happen mostly at startup.
class SqliteSessionStore final : public SessionStore {
 public:
  // Opens or creates the database at `path`, switches it to WAL and migrates its
  // schema. A file that is not a database → DATA_LOSS; a schema newer than this
  // build → FAILED_PRECONDITION; a directory that cannot be written → UNAVAILABLE.
  static StatusOr<std::unique_ptr<SqliteSessionStore>> Open(const std::string& path,
                                                            const SqliteStoreOptions& options = {});
  ~SqliteSessionStore() override;
  SqliteSessionStore(const SqliteSessionStore&) = delete;
  SqliteSessionStore& operator=(const SqliteSessionStore&) = delete;

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

 private:
  struct Connection;  // the sqlite3 handle and its prepared statements
  explicit SqliteSessionStore(std::unique_ptr<Connection> connection);

  std::mutex mutex_;
  std::unique_ptr<Connection> connection_;  // guarded by mutex_
};

}  // namespace relmap::session
