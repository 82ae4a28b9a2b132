// PostgresSessionStore: each operation is one transaction on a pooled
// connection; each write first fences itself on the session's owner row, which
// also serialises the writes to one session.
#include "session/store/postgres/postgres_session_store.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <random>
#include <utility>

#include "session/records/snapshot_codec.h"
#include "session/store/postgres/postgres_connection.h"
#include "session/store/postgres/postgres_schema.h"
#include "session/store/store_contract.h"

namespace relmap::session {
namespace {

// PostgreSQL keeps at most 63 bytes of application_name (NAMEDATALEN - 1) and
// turns anything but printable ASCII into '?': an owner id beyond either would
// not be found in pg_stat_activity, and its owner would look dead.
constexpr std::size_t kMaxOwnerIdLength = 63;

bool PrintableAscii(char c) { return c >= 0x20 && c < 0x7F; }

std::string GeneratedOwnerId() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  std::string hostname;
  for (const char* c = host; *c != '\0'; ++c) {
    hostname.push_back(PrintableAscii(*c) && *c != ' ' ? *c : '_');
  }
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, "-%d-%08x", static_cast<int>(getpid()),
                static_cast<unsigned>(std::random_device()()));
  const std::string prefix = "relmap-";
  const std::size_t room = kMaxOwnerIdLength - prefix.size() - std::strlen(suffix);
  return prefix + hostname.substr(0, room) + suffix;
}

Status CheckOptions(const PostgresStoreOptions& options) {
  if (options.lease_ttl.count() < 1) return InvalidArgumentError("lease TTL must be positive");
  if (options.max_connections < 1) {
    return InvalidArgumentError("max_connections must be at least 1");
  }
  if (options.connect_timeout.count() < 1) {
    return InvalidArgumentError("connect timeout must be at least 1 s");
  }
  if (options.lock_timeout.count() < 1) {
    return InvalidArgumentError("lock timeout must be positive");
  }
  const std::string& id = options.owner_id;
  if (id.size() > kMaxOwnerIdLength || !std::all_of(id.begin(), id.end(), PrintableAscii)) {
    return InvalidArgumentError("owner id " + Quoted(id) +
                                " is not 1 to 63 printable ASCII characters");
  }
  return OkStatus();
}

constexpr char kSessionColumns[] =
    "id, token_hash, created_unix_micros, config, cmm_variant, cmm_alpha, cmm_regularization,"
    " cmm_seed, cmm_pseudo_density, cmm_first_sample_mean, cmm_stale_weights,"
    " cmm_nearest_candidate_only, cmm_truncated_recheck, cmm_skip_likelihood_check,"
    " feature_dimension";

// A session's record and counters, as LoadSession and ListSessions select them.
constexpr char kRecordColumns[] =
    "id, token_hash, created_unix_micros, config, cmm_variant, cmm_alpha, cmm_regularization,"
    " cmm_seed, cmm_pseudo_density, cmm_first_sample_mean, cmm_stale_weights,"
    " cmm_nearest_candidate_only, cmm_truncated_recheck, cmm_skip_likelihood_check,"
    " feature_dimension, frames_computed, interactions,"
    " COALESCE(last_used_unix_micros, created_unix_micros)";
constexpr int kRecordColumnCount = 18;

// The record in row `i` of a result that selected kRecordColumns first.
StatusOr<SessionRecord> RecordOfRow(const PgResult& rows, int i) {
  SessionRecord r;
  r.id = rows.Text(i, 0);
  r.token_hash = rows.Text(i, 1);
  r.created_at = Timestamp(std::chrono::microseconds(rows.Int8(i, 2)));
  r.config = rows.Text(i, 3);
  const std::string variant = rows.Text(i, 4);
  auto parsed = cmm::ParseVariant(variant);
  if (!parsed.ok()) {
    return DataLossError("session " + Quoted(r.id) + " has unknown CMM variant " + Quoted(variant));
  }
  // The options not stored field by field are the variant's preset.
  r.cmm_config = cmm::CmmConfig::ForVariant(*parsed);
  r.cmm_config.alpha = rows.Float8(i, 5);
  r.cmm_config.regularization = rows.Float8(i, 6);
  r.cmm_config.seed = static_cast<std::uint64_t>(rows.Int8(i, 7));
  for (std::size_t k = 0; k < std::size(kPaper2018SwitchFields); ++k) {
    r.cmm_config.switches.*kPaper2018SwitchFields[k] = rows.Bool(i, 8 + static_cast<int>(k));
  }
  r.feature_dimension = rows.Int4(i, 14);
  r.counters.frames_computed = rows.Int8(i, 15);
  r.counters.interactions = rows.Int8(i, 16);
  r.last_used = Timestamp(std::chrono::microseconds(rows.Int8(i, 17)));
  return r;
}

// "now() + the lease", with the lease in milliseconds as parameter `$n`. The
// database's clock, not the servers': their clocks need not agree.
std::string LeaseEnd(int n) {
  return "now() + $" + std::to_string(n) + " * interval '1 millisecond'";
}

}  // namespace

StatusOr<std::unique_ptr<PostgresSessionStore>> PostgresSessionStore::Open(
    const std::string& conninfo, const PostgresStoreOptions& options) {
  if (Status status = CheckOptions(options); !status.ok()) return status;
  PostgresStoreOptions resolved = options;
  if (resolved.owner_id.empty()) resolved.owner_id = GeneratedOwnerId();
  auto pool = std::make_unique<PostgresConnectionPool>(
      PgConnectionSettings{conninfo, resolved.owner_id, resolved.connect_timeout,
                           resolved.lock_timeout},
      resolved.max_connections);
  {
    // Connect now, so that a wrong address fails at startup, not at the first call.
    auto connection = pool->Take();
    if (!connection.ok()) return connection.status();
    if (Status status = MigratePostgresSchema(**connection); !status.ok()) return status;
  }
  return std::unique_ptr<PostgresSessionStore>(new PostgresSessionStore(std::move(pool), resolved));
}

PostgresSessionStore::PostgresSessionStore(std::unique_ptr<PostgresConnectionPool> pool,
                                           const PostgresStoreOptions& options)
    : pool_(std::move(pool)), owner_id_(options.owner_id), lease_ttl_(options.lease_ttl) {}

PostgresSessionStore::~PostgresSessionStore() {
  // A server that stops hands its sessions over at once rather than when its
  // connections are seen gone. Best effort, like ReleaseOwnership.
  auto connection = pool_->Take();
  if (!connection.ok()) return;
  (void)(*connection)
      ->ExecuteRetryingOnce(
          "UPDATE session_owners SET owner = NULL, lease_expires_at = NULL WHERE owner = $1",
          PgParams().Text(owner_id_), "releasing every session");
}

std::optional<std::int64_t> PostgresSessionStore::HeldEpoch(std::string_view session_id) {
  std::lock_guard lock(epochs_mutex_);
  auto it = epochs_.find(session_id);
  if (it == epochs_.end()) return std::nullopt;
  return it->second;
}

void PostgresSessionStore::Remember(std::string_view session_id,
                                    std::optional<std::int64_t> epoch) {
  std::lock_guard lock(epochs_mutex_);
  auto it = epochs_.find(session_id);
  if (!epoch.has_value()) {
    if (it != epochs_.end()) epochs_.erase(it);
  } else if (it == epochs_.end()) {
    epochs_.emplace(std::string(session_id), *epoch);
  } else {
    // Epochs only grow: of two racing acquisitions, the later one counts.
    it->second = std::max(it->second, *epoch);
  }
}

namespace {

// A session's owner row. Every session has one: CreateSession inserts it and
// DeleteSession deletes it in the transaction that does the same to the session.
struct OwnerRow {
  std::string owner;  // "" when released
  std::int64_t epoch = 0;
  bool lease_live = false;
  bool owner_connected = false;  // some connection carries the owner's application_name
  std::string lease_end;         // ISO 8601, UTC
};

// The owner row of `session_id` (NOT_FOUND if the session does not exist),
// locked until the transaction ends if `lock`: two servers acquiring at once
// then decide one after the other, the second on the row as the first left it.
// A dead server's backends leave pg_stat_activity as soon as PostgreSQL sees its
// sockets closed: at once after kill -9 of a process on a live machine.
StatusOr<OwnerRow> ReadOwner(PgConnection& connection, std::string_view session_id, bool lock) {
  auto row = connection.Execute(
      std::string("SELECT o.owner, o.epoch, COALESCE(o.lease_expires_at > now(), false),"
                  " EXISTS (SELECT 1 FROM pg_stat_activity AS a"
                  " WHERE a.application_name = o.owner),"
                  " COALESCE(to_char(o.lease_expires_at AT TIME ZONE 'UTC',"
                  " 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), '')"
                  " FROM session_owners AS o WHERE o.session_id = $1") +
          (lock ? " FOR UPDATE OF o" : ""),
      PgParams().Text(session_id), "reading the owner");
  if (!row.ok()) return row.status();
  if (row->rows() == 0) return SessionNotFound(session_id);
  return OwnerRow{row->IsNull(0, 0) ? std::string() : row->Text(0, 0), row->Int8(0, 1),
                  row->Bool(0, 2), row->Bool(0, 3), row->Text(0, 4)};
}

// Within an open transaction: checks that this store still owns `session_id`
// under `epoch`, renews its lease and locks the owner row until the transaction
// ends (a takeover waits for this write, or this write sees the takeover).
// Returns the session's feature dimension. A session that does not exist →
// NOT_FOUND; owned by another store, or not by this one → ABORTED.
StatusOr<int> Fence(PgConnection& connection, std::string_view session_id,
                    const std::string& owner_id, std::optional<std::int64_t> epoch,
                    std::chrono::milliseconds lease_ttl) {
  if (epoch.has_value()) {
    auto fenced = connection.Execute(
        "UPDATE session_owners AS o SET lease_expires_at = " + LeaseEnd(3) +
            " FROM sessions AS s WHERE o.session_id = $1 AND s.id = $1 AND o.owner = $2"
            " AND o.epoch = $4 RETURNING s.feature_dimension",
        PgParams().Text(session_id).Text(owner_id).Int8(lease_ttl.count()).Int8(*epoch),
        "checking ownership");
    if (!fenced.ok()) return fenced.status();
    if (fenced->rows() == 1) return fenced->Int4(0, 0);
  }
  auto row = ReadOwner(connection, session_id, /*lock=*/false);
  if (!row.ok()) return row.status();
  const std::string& current = row->owner;
  if (epoch.has_value() && !current.empty() && current != owner_id) {
    return Status(StatusCode::kAborted,
                  "session " + Quoted(session_id) + " was taken over by server " + Quoted(current));
  }
  return Status(StatusCode::kAborted,
                "session " + Quoted(session_id) + " is not owned by this server (" + owner_id +
                    "); " +
                    (current.empty() ? "nobody owns it" : "server " + Quoted(current) + " does") +
                    ": acquire it before writing");
}

}  // namespace

Status PostgresSessionStore::CreateSession(const SessionRecord& r) {
  if (Status status = CheckRecord(r); !status.ok()) return status;
  const cmm::Paper2018Switches& s = r.cmm_config.switches;
  static_assert(std::size(kPaper2018SwitchFields) == 6, "a new switch needs a column and a bind");
  std::int64_t epoch = 0;
  Status created = InTransaction([&](PgConnection& c) -> Status {
    auto inserted =
        c.Execute(std::string("INSERT INTO sessions (") + kSessionColumns +
                      ") VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15)"
                      " ON CONFLICT (id) DO NOTHING",
                  PgParams()
                      .Text(r.id)
                      .Text(r.token_hash)
                      .Int8(r.created_at.time_since_epoch().count())
                      .Bytea(r.config)
                      .Text(cmm::VariantName(r.cmm_config.variant))
                      .Float8(r.cmm_config.alpha)
                      .Float8(r.cmm_config.regularization)
                      .Int8(static_cast<std::int64_t>(r.cmm_config.seed))  // its bit pattern
                      .Bool(s.pseudo_density)
                      .Bool(s.first_sample_mean)
                      .Bool(s.stale_weights)
                      .Bool(s.nearest_candidate_only)
                      .Bool(s.truncated_recheck)
                      .Bool(s.skip_likelihood_check)
                      .Int4(r.feature_dimension),
                  "creating a session");
    if (!inserted.ok()) return inserted.status();
    if (inserted->AffectedRows() == 0) {
      return {StatusCode::kAlreadyExists, "session " + Quoted(r.id) + " already exists"};
    }
    auto owned = c.Execute(
        "INSERT INTO session_owners (session_id, owner, epoch, lease_expires_at)"
        " VALUES ($1, $2, nextval('session_owner_epochs'), " +
            LeaseEnd(3) + ") RETURNING epoch",
        PgParams().Text(r.id).Text(owner_id_).Int8(lease_ttl_.count()), "owning the new session");
    if (!owned.ok()) return owned.status();
    epoch = owned->Int8(0, 0);
    return OkStatus();
  });
  if (!created.ok()) return created;
  Remember(r.id, epoch);
  return OkStatus();
}

StatusOr<SessionRecord> PostgresSessionStore::LoadSession(std::string_view id) {
  auto connection = pool_->Take();
  if (!connection.ok()) return connection.status();
  auto row = (*connection)
                 ->ExecuteRetryingOnce(
                     std::string("SELECT ") + kRecordColumns + " FROM sessions WHERE id = $1",
                     PgParams().Text(id), "loading a session");
  if (!row.ok()) return row.status();
  if (row->rows() == 0) return SessionNotFound(id);
  return RecordOfRow(*row, 0);
}

StatusOr<std::vector<SessionSummary>> PostgresSessionStore::ListSessions() {
  auto connection = pool_->Take();
  if (!connection.ok()) return connection.status();
  auto rows =
      (*connection)
          ->ExecuteRetryingOnce(std::string("SELECT ") + kRecordColumns +
                                    ", samples_non_moveable, samples_moveable, model_sample_count,"
                                    " model_components_non_moveable, model_components_moveable"
                                    " FROM sessions ORDER BY id",
                                {}, "listing sessions");
  if (!rows.ok()) return rows.status();
  std::vector<SessionSummary> sessions;
  sessions.reserve(static_cast<std::size_t>(rows->rows()));
  constexpr int k = kRecordColumnCount;
  for (int i = 0; i < rows->rows(); ++i) {
    auto record = RecordOfRow(*rows, i);
    if (!record.ok()) return record.status();
    SessionSummary summary;
    summary.record = std::move(record).value();
    summary.samples[0] = rows->Int8(i, k);
    summary.samples[1] = rows->Int8(i, k + 1);
    if (!rows->IsNull(i, k + 2)) {
      summary.model = ModelSummary{rows->Int8(i, k + 2),
                                   {rows->Int8(i, k + 3), rows->Int8(i, k + 4)},
                                   summary.record.last_used};
    }
    sessions.push_back(std::move(summary));
  }
  return sessions;
}

Status PostgresSessionStore::DeleteSession(std::string_view id) {
  Status deleted = InTransaction([&](PgConnection& c) -> Status {
    // The owner row first: deleting it waits for a write in flight (which holds
    // it), so the samples deleted next include that write's.
    const char* statements[] = {
        "DELETE FROM session_owners WHERE session_id = $1",
        "DELETE FROM samples WHERE session_id = $1",
        "DELETE FROM snapshots WHERE session_id = $1",
        "DELETE FROM sessions WHERE id = $1",
    };
    std::int64_t deleted_sessions = 0;
    for (const char* sql : statements) {
      auto result = c.Execute(sql, PgParams().Text(id), "deleting a session");
      if (!result.ok()) return result.status();
      deleted_sessions = result->AffectedRows();
    }
    return deleted_sessions == 0 ? SessionNotFound(id) : OkStatus();
  });
  if (!deleted.ok()) return deleted;
  Remember(id, std::nullopt);
  return OkStatus();
}

Status PostgresSessionStore::InTransaction(const std::function<Status(PgConnection&)>& body) {
  auto connection = pool_->Take();
  if (!connection.ok()) return connection.status();
  PgTransaction transaction(**connection);
  if (Status status = transaction.Begin(); !status.ok()) return status;
  if (Status status = body(**connection); !status.ok()) return status;
  return transaction.Commit();
}

Status PostgresSessionStore::FencedWrite(std::string_view session_id,
                                         const std::function<Status(PgConnection&, int)>& body) {
  const std::optional<std::int64_t> epoch = HeldEpoch(session_id);
  return InTransaction([&](PgConnection& c) -> Status {
    auto dimension = Fence(c, session_id, owner_id_, epoch, lease_ttl_);
    if (!dimension.ok()) {
      if (dimension.status().code() == StatusCode::kAborted) Remember(session_id, std::nullopt);
      return dimension.status();
    }
    return body(c, *dimension);
  });
}

StatusOr<std::int64_t> PostgresSessionStore::AppendSample(std::string_view session_id,
                                                          std::string_view request_id,
                                                          std::span<const double> features,
                                                          int label) {
  if (Status status = CheckSample(request_id, features, label); !status.ok()) return status;
  const std::string blob = EncodeFeatures(features);
  std::int64_t sequence = 0;
  const Status written = FencedWrite(session_id, [&](PgConnection& c, int dimension) -> Status {
    if (Status status = CheckFeatureCount(session_id, features, dimension); !status.ok()) {
      return status;
    }
    // One statement: the sample already stored under this request id, if any,
    // and the next sequence number (the owner row's lock keeps it ours until
    // commit).
    auto existing = c.Execute(
        "SELECT (SELECT COALESCE(MAX(sequence) + 1, 0) FROM samples WHERE session_id = $1),"
        " x.sequence, x.features, x.label FROM (SELECT 1) AS one"
        " LEFT JOIN samples AS x ON x.session_id = $1 AND x.request_id = $2",
        PgParams().Text(session_id).Text(request_id), "looking up the request id");
    if (!existing.ok()) return existing.status();
    if (!existing->IsNull(0, 1)) {
      // A retried request: answer as the first time, without a second row (the
      // first was committed before it was acknowledged).
      if (existing->Bytes(0, 2) != blob || existing->Int4(0, 3) != label) {
        return RequestIdReused(session_id, request_id);
      }
      sequence = existing->Int8(0, 1);
      return OkStatus();
    }
    sequence = existing->Int8(0, 0);
    // The label's count in the same statement, so that the counts are the stored
    // samples'.
    return c
        .Execute(
            "WITH stored AS (INSERT INTO samples (session_id, sequence, request_id, features,"
            " label) VALUES ($1, $2, $3, $4, $5) RETURNING label)"
            " UPDATE sessions SET"
            " samples_non_moveable = samples_non_moveable + (stored.label = 0)::int,"
            " samples_moveable = samples_moveable + (stored.label = 1)::int"
            " FROM stored WHERE sessions.id = $1",
            PgParams().Text(session_id).Int8(sequence).Text(request_id).Bytea(blob).Int4(label),
            "appending a sample")
        .status();
  });
  if (!written.ok()) return written;
  return sequence;
}

StatusOr<std::vector<StoredSample>> PostgresSessionStore::LoadSamples(std::string_view session_id) {
  auto connection = pool_->Take();
  if (!connection.ok()) return connection.status();
  // One statement, one snapshot: the existence check and the rows agree.
  auto rows = (*connection)
                  ->ExecuteRetryingOnce(
                      "SELECT s.feature_dimension, x.sequence, x.request_id, x.features, x.label"
                      " FROM sessions AS s LEFT JOIN samples AS x ON x.session_id = s.id"
                      " WHERE s.id = $1 ORDER BY x.sequence",
                      PgParams().Text(session_id), "loading samples");
  if (!rows.ok()) return rows.status();
  if (rows->rows() == 0) return SessionNotFound(session_id);
  const int dimension = rows->Int4(0, 0);
  std::vector<StoredSample> samples;
  if (rows->IsNull(0, 1)) return samples;  // the LEFT JOIN's row of a session without samples
  samples.reserve(static_cast<std::size_t>(rows->rows()));
  for (int i = 0; i < rows->rows(); ++i) {
    StoredSample sample;
    sample.sequence = rows->Int8(i, 1);
    sample.request_id = rows->Text(i, 2);
    auto decoded = DecodeFeatures(rows->Bytes(i, 3), dimension, session_id, sample.sequence);
    if (!decoded.ok()) return decoded.status();
    sample.features = std::move(decoded).value();
    sample.label = rows->Int4(i, 4);
    samples.push_back(std::move(sample));
  }
  return samples;
}

Status PostgresSessionStore::SaveSnapshot(std::string_view session_id,
                                          const cmm::CmmSnapshot& snapshot,
                                          std::int64_t sample_count) {
  if (Status status = CheckSnapshotSampleCount(sample_count); !status.ok()) return status;
  auto blob = EncodeSnapshot(snapshot);
  if (!blob.ok()) return blob.status();
  return FencedWrite(session_id, [&](PgConnection& c, int dimension) -> Status {
    auto stored =
        c.Execute("SELECT COALESCE(MAX(sequence) + 1, 0) FROM samples WHERE session_id = $1",
                  PgParams().Text(session_id), "counting samples");
    if (!stored.ok()) return stored.status();
    if (Status status = CheckSnapshotAgainstSession(session_id, snapshot, sample_count, dimension,
                                                    stored->Int8(0, 0));
        !status.ok()) {
      return status;
    }
    return c
        .Execute(
            "INSERT INTO snapshots (session_id, sample_count, snapshot) VALUES ($1, $2, $3)"
            " ON CONFLICT (session_id) DO UPDATE SET sample_count = excluded.sample_count,"
            " snapshot = excluded.snapshot",
            PgParams().Text(session_id).Int8(sample_count).Bytea(*blob), "saving a snapshot")
        .status();
  });
}

StatusOr<std::optional<StoredSnapshot>> PostgresSessionStore::LoadLatestSnapshot(
    std::string_view session_id) {
  std::string blob;
  std::int64_t sample_count = 0;
  {
    auto connection = pool_->Take();
    if (!connection.ok()) return connection.status();
    auto row = (*connection)
                   ->ExecuteRetryingOnce(
                       "SELECT n.sample_count, n.snapshot FROM sessions AS s"
                       " LEFT JOIN snapshots AS n ON n.session_id = s.id WHERE s.id = $1",
                       PgParams().Text(session_id), "loading the snapshot");
    if (!row.ok()) return row.status();
    if (row->rows() == 0) return SessionNotFound(session_id);
    if (row->IsNull(0, 0)) return std::optional<StoredSnapshot>();
    sample_count = row->Int8(0, 0);
    blob = row->Text(0, 1);
  }
  // Decoding (and its checksum) runs with the connection back in the pool.
  auto snapshot = DecodeSnapshot(blob);
  if (!snapshot.ok()) return SnapshotDecodeError(session_id, snapshot.status());
  return std::optional<StoredSnapshot>(StoredSnapshot{std::move(snapshot).value(), sample_count});
}

Status PostgresSessionStore::IncrementCounters(std::string_view session_id,
                                               const SessionCounters& delta) {
  if (Status status = CheckCounterDelta(delta); !status.ok()) return status;
  return FencedWrite(session_id, [&](PgConnection& c, int) -> Status {
    return c
        .Execute(
            "UPDATE sessions SET frames_computed = frames_computed + $2,"
            " interactions = interactions + $3 WHERE id = $1",
            PgParams().Text(session_id).Int8(delta.frames_computed).Int8(delta.interactions),
            "incrementing counters")
        .status();
  });
}

Status PostgresSessionStore::RecordModelSummary(std::string_view session_id,
                                                const ModelSummary& summary) {
  if (Status status = CheckModelSummary(summary); !status.ok()) return status;
  return FencedWrite(session_id, [&](PgConnection& c, int) -> Status {
    // A summary only saves loading a session to list it, and the samples determine it:
    // its commit need not wait for the WAL flush (a server crash may undo it, never tear
    // it), which would double the synchronous commits of a one-sample call.
    if (auto asynchronous =
            c.Execute("SET LOCAL synchronous_commit = off", {}, "recording a model summary");
        !asynchronous.ok()) {
      return asynchronous.status();
    }
    auto stored =
        c.Execute("SELECT COALESCE(MAX(sequence) + 1, 0) FROM samples WHERE session_id = $1",
                  PgParams().Text(session_id), "counting samples");
    if (!stored.ok()) return stored.status();
    if (Status status = CheckModelSummaryAgainstSession(session_id, summary, stored->Int8(0, 0));
        !status.ok()) {
      return status;
    }
    return c
        .Execute(
            "UPDATE sessions SET model_sample_count = $2, model_components_non_moveable = $3,"
            " model_components_moveable = $4, last_used_unix_micros = $5 WHERE id = $1"
            " AND (model_sample_count IS NULL OR model_sample_count < $2"
            " OR (model_sample_count = $2 AND last_used_unix_micros <= $5))",
            PgParams()
                .Text(session_id)
                .Int8(summary.sample_count)
                .Int8(summary.components[0])
                .Int8(summary.components[1])
                .Int8(summary.last_used.time_since_epoch().count()),
            "recording a model summary")
        .status();
  });
}

StatusOr<SessionStore::Ownership> PostgresSessionStore::AcquireOwnership(
    std::string_view session_id) {
  const std::optional<std::int64_t> epoch = HeldEpoch(session_id);
  std::optional<std::int64_t> taken_epoch;  // set when taken now
  const Status acquired = InTransaction([&](PgConnection& c) -> Status {
    auto row = ReadOwner(c, session_id, /*lock=*/true);
    if (!row.ok()) return row.status();
    if (row->owner == owner_id_ && epoch == row->epoch) {
      return c
          .Execute("UPDATE session_owners SET lease_expires_at = " + LeaseEnd(2) +
                       " WHERE session_id = $1",
                   PgParams().Text(session_id).Int8(lease_ttl_.count()), "renewing the lease")
          .status();
    }
    // Ours under another epoch (an acquisition whose commit was lost) is taken
    // again like a free session: this store's copy is not known to be current.
    if (!row->owner.empty() && row->owner != owner_id_ && row->lease_live && row->owner_connected) {
      return Status(StatusCode::kUnavailable, "session " + Quoted(session_id) +
                                                  " is owned by server " + Quoted(row->owner) +
                                                  " (lease until " + row->lease_end + ")")
          .WithReason(ErrorReason::kSessionOwnedElsewhere, {{"sessionId", std::string(session_id)},
                                                            {"owner", row->owner},
                                                            {"leaseExpiresAt", row->lease_end}});
    }
    auto taken = c.Execute(
        "UPDATE session_owners SET owner = $2, epoch = nextval('session_owner_epochs'),"
        " lease_expires_at = " +
            LeaseEnd(3) + " WHERE session_id = $1 RETURNING epoch",
        PgParams().Text(session_id).Text(owner_id_).Int8(lease_ttl_.count()), "taking the session");
    if (!taken.ok()) return taken.status();
    taken_epoch = taken->Int8(0, 0);
    return OkStatus();
  });
  if (!acquired.ok()) return acquired;
  if (!taken_epoch.has_value()) return Ownership{.held_throughout = true};
  Remember(session_id, *taken_epoch);
  return Ownership{.held_throughout = false};
}

void PostgresSessionStore::ReleaseOwnership(std::string_view session_id) {
  const std::optional<std::int64_t> epoch = HeldEpoch(session_id);
  if (!epoch.has_value()) return;
  Remember(session_id, std::nullopt);
  auto connection = pool_->Take();
  if (!connection.ok()) return;
  // Only if it is still ours: a session taken over meanwhile stays with its new owner.
  (void)(*connection)
      ->ExecuteRetryingOnce(
          "UPDATE session_owners SET owner = NULL, lease_expires_at = NULL"
          " WHERE session_id = $1 AND owner = $2 AND epoch = $3",
          PgParams().Text(session_id).Text(owner_id_).Int8(*epoch), "releasing a session");
}

}  // namespace relmap::session
