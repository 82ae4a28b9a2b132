// Schema versions of the SQLite session store. A migration is appended, never
// edited: a database on disk may be at any earlier version.
#include "session/store/sqlite/sqlite_schema.h"

#include <iterator>
#include <string>
#include <string_view>

#include "session/store/sqlite/sqlite_statement.h"

namespace relmap::session {
namespace {

// kSqliteMigrations[v] takes the schema from version v to v + 1. STRICT tables make
// SQLite refuse a value of the wrong type instead of converting it.
constexpr std::string_view kSqliteMigrations[] = {
    // 0 → 1: sessions, their samples and the latest snapshot of each.
    R"sql(
CREATE TABLE sessions (
  id TEXT PRIMARY KEY NOT NULL,
  token_hash TEXT NOT NULL,
  created_unix_micros INTEGER NOT NULL,
  config BLOB NOT NULL,
  cmm_variant TEXT NOT NULL,
  cmm_alpha REAL NOT NULL,
  cmm_regularization REAL NOT NULL,
  cmm_seed INTEGER NOT NULL,
  cmm_pseudo_density INTEGER NOT NULL,
  cmm_first_sample_mean INTEGER NOT NULL,
  cmm_stale_weights INTEGER NOT NULL,
  cmm_nearest_candidate_only INTEGER NOT NULL,
  cmm_truncated_recheck INTEGER NOT NULL,
  cmm_skip_likelihood_check INTEGER NOT NULL,
  feature_dimension INTEGER NOT NULL CHECK (feature_dimension > 0),
  frames_computed INTEGER NOT NULL DEFAULT 0,
  interactions INTEGER NOT NULL DEFAULT 0
) STRICT;
CREATE TABLE samples (
  session_id TEXT NOT NULL REFERENCES sessions (id),
  sequence INTEGER NOT NULL CHECK (sequence >= 0),
  request_id TEXT NOT NULL,
  features BLOB NOT NULL,
  label INTEGER NOT NULL CHECK (label IN (0, 1)),
  PRIMARY KEY (session_id, sequence),
  UNIQUE (session_id, request_id)
) STRICT;
CREATE TABLE snapshots (
  session_id TEXT PRIMARY KEY NOT NULL REFERENCES sessions (id),
  sample_count INTEGER NOT NULL CHECK (sample_count >= 0),
  snapshot BLOB NOT NULL
) STRICT;
)sql",
    // 1 → 2 (December 2026): "corrected" names a new classifier; the sessions
    // created under the old one keep it, by its new name.
    R"sql(
UPDATE sessions SET cmm_variant = 'corrected_v1' WHERE cmm_variant = 'corrected';
)sql",
    // 2 → 3 (December 2026): what ListSessions shows of a session without loading it.
    // The samples per label are counted here once, then by every append; the model
    // summary (NULL until a server records one) is filled when a session is next
    // loaded or listed.
    R"sql(
ALTER TABLE sessions ADD COLUMN samples_non_moveable INTEGER NOT NULL DEFAULT 0;
ALTER TABLE sessions ADD COLUMN samples_moveable INTEGER NOT NULL DEFAULT 0;
ALTER TABLE sessions ADD COLUMN model_sample_count INTEGER;
ALTER TABLE sessions ADD COLUMN model_components_non_moveable INTEGER;
ALTER TABLE sessions ADD COLUMN model_components_moveable INTEGER;
ALTER TABLE sessions ADD COLUMN last_used_unix_micros INTEGER;
UPDATE sessions SET
  samples_non_moveable = (SELECT COUNT(*) FROM samples WHERE session_id = sessions.id AND label = 0),
  samples_moveable = (SELECT COUNT(*) FROM samples WHERE session_id = sessions.id AND label = 1);
)sql",
};

}  // namespace

int CurrentSchemaVersion() { return static_cast<int>(std::size(kSqliteMigrations)); }

Status MigrateSchema(sqlite3* db) {
  Transaction transaction(db);
  if (Status status = transaction.BeginWrite(); !status.ok()) return status;
  if (Status status = Execute(db,
                              "CREATE TABLE IF NOT EXISTS schema_version ("
                              "  id INTEGER PRIMARY KEY CHECK (id = 1),"
                              "  version INTEGER NOT NULL) STRICT");
      !status.ok()) {
    return status;
  }
  auto select = Statement::Prepare(db, "SELECT version FROM schema_version WHERE id = 1");
  if (!select.ok()) return select.status();
  auto row = select->Step();
  if (!row.ok()) return row.status();
  const std::int64_t version = *row ? select->Int64(0) : 0;
  select->Reset();

  const int current = CurrentSchemaVersion();
  if (version > current) {
    return FailedPreconditionError("database schema version " + std::to_string(version) +
                                   " is newer than this build's " + std::to_string(current) +
                                   "; upgrade the server");
  }
  if (version < 0) return DataLossError("database schema version " + std::to_string(version));
  if (version == current) return OkStatus();
  for (std::int64_t v = version; v < current; ++v) {
    if (Status status = Execute(db, kSqliteMigrations[v]); !status.ok()) return status;
  }
  auto update = Statement::Prepare(db,
                                   "INSERT INTO schema_version (id, version) VALUES (1, ?1) "
                                   "ON CONFLICT (id) DO UPDATE SET version = excluded.version");
  if (!update.ok()) return update.status();
  if (Status status = update->Bind(static_cast<std::int64_t>(current)); !status.ok()) return status;
  if (Status status = update->Run(); !status.ok()) return status;
  update->Reset();
  return transaction.Commit();
}

}  // namespace relmap::session
