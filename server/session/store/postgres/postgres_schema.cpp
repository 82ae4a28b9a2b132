// Schema versions of the PostgreSQL session store. A migration is appended,
// never edited: a database may be at any earlier version.
#include "session/store/postgres/postgres_schema.h"

#include <iterator>
#include <string>
#include <string_view>

namespace relmap::session {
namespace {

// kPostgresMigrations[v] takes the schema from version v to v + 1. Ids are COLLATE "C",
// so that they compare and sort by their bytes, as in the SQLite store. Features
// and snapshots are the same little-endian blobs as there: bit for bit, by
// construction.
constexpr std::string_view kPostgresMigrations[] = {
    // 0 → 1: sessions, their samples, the latest snapshot of each, and which
    // server owns each for writing.
    R"sql(
CREATE TABLE sessions (
  id text COLLATE "C" PRIMARY KEY,
  token_hash text NOT NULL,
  created_unix_micros bigint NOT NULL,
  config bytea NOT NULL,
  cmm_variant text NOT NULL,
  cmm_alpha double precision NOT NULL,
  cmm_regularization double precision NOT NULL,
  cmm_seed bigint NOT NULL,
  cmm_pseudo_density boolean NOT NULL,
  cmm_first_sample_mean boolean NOT NULL,
  cmm_stale_weights boolean NOT NULL,
  cmm_nearest_candidate_only boolean NOT NULL,
  cmm_truncated_recheck boolean NOT NULL,
  cmm_skip_likelihood_check boolean NOT NULL,
  feature_dimension integer NOT NULL CHECK (feature_dimension > 0),
  frames_computed bigint NOT NULL DEFAULT 0,
  interactions bigint NOT NULL DEFAULT 0
);
CREATE TABLE samples (
  session_id text COLLATE "C" NOT NULL REFERENCES sessions (id),
  sequence bigint NOT NULL CHECK (sequence >= 0),
  request_id text COLLATE "C" NOT NULL,
  features bytea NOT NULL,
  label integer NOT NULL CHECK (label IN (0, 1)),
  PRIMARY KEY (session_id, sequence),
  UNIQUE (session_id, request_id)
);
CREATE TABLE snapshots (
  session_id text COLLATE "C" PRIMARY KEY REFERENCES sessions (id),
  sample_count bigint NOT NULL CHECK (sample_count >= 0),
  snapshot bytea NOT NULL
);
-- Epochs come from one sequence: a fencing token is never reused, not even by a
-- later session under the same id.
CREATE SEQUENCE session_owner_epochs;
CREATE TABLE session_owners (
  session_id text COLLATE "C" PRIMARY KEY REFERENCES sessions (id),
  owner text,  -- the owning store's owner id; NULL when released
  epoch bigint NOT NULL,
  lease_expires_at timestamptz
);
CREATE INDEX session_owners_by_owner ON session_owners (owner);
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
ALTER TABLE sessions
  ADD COLUMN samples_non_moveable bigint NOT NULL DEFAULT 0,
  ADD COLUMN samples_moveable bigint NOT NULL DEFAULT 0,
  ADD COLUMN model_sample_count bigint,
  ADD COLUMN model_components_non_moveable bigint,
  ADD COLUMN model_components_moveable bigint,
  ADD COLUMN last_used_unix_micros bigint;
UPDATE sessions AS s
  SET samples_non_moveable = n.non_moveable, samples_moveable = n.moveable
  FROM (SELECT session_id, COUNT(*) FILTER (WHERE label = 0) AS non_moveable,
               COUNT(*) FILTER (WHERE label = 1) AS moveable
        FROM samples GROUP BY session_id) AS n
  WHERE n.session_id = s.id;
)sql",
};

// pg_advisory_xact_lock's key for migrations: "relmapSc" in ASCII.
constexpr std::int64_t kMigrationLock = 0x72656c6d61705363;

}  // namespace

int CurrentPostgresSchemaVersion() { return static_cast<int>(std::size(kPostgresMigrations)); }

Status MigratePostgresSchema(PgConnection& connection) {
  PgTransaction transaction(connection);
  if (Status status = transaction.Begin(); !status.ok()) return status;
  // CREATE TABLE IF NOT EXISTS is not safe against a concurrent one: the lock
  // makes the second server wait, then find the schema current.
  if (auto locked = connection.Execute("SELECT pg_advisory_xact_lock($1)",
                                       PgParams().Int8(kMigrationLock), "locking the schema");
      !locked.ok()) {
    return locked.status();
  }
  if (Status status = connection.ExecuteScript("CREATE TABLE IF NOT EXISTS schema_version ("
                                               "  id integer PRIMARY KEY CHECK (id = 1),"
                                               "  version bigint NOT NULL)",
                                               "creating schema_version");
      !status.ok()) {
    return status;
  }
  auto row = connection.Execute("SELECT version FROM schema_version WHERE id = 1", {},
                                "reading the schema version");
  if (!row.ok()) return row.status();
  const std::int64_t version = row->rows() > 0 ? row->Int8(0, 0) : 0;

  const int current = CurrentPostgresSchemaVersion();
  if (version > current) {
    return FailedPreconditionError("database schema version " + std::to_string(version) +
                                   " is newer than this build's " + std::to_string(current) +
                                   "; upgrade the server");
  }
  if (version < 0) return DataLossError("database schema version " + std::to_string(version));
  if (version == current) return transaction.Commit();
  for (std::int64_t v = version; v < current; ++v) {
    if (Status status = connection.ExecuteScript(
            kPostgresMigrations[v], "migrating the schema to version " + std::to_string(v + 1));
        !status.ok()) {
      return status;
    }
  }
  if (auto updated =
          connection.Execute("INSERT INTO schema_version (id, version) VALUES (1, $1)"
                             " ON CONFLICT (id) DO UPDATE SET version = excluded.version",
                             PgParams().Int8(current), "recording the schema version");
      !updated.ok()) {
    return updated.status();
  }
  return transaction.Commit();
}

}  // namespace relmap::session
