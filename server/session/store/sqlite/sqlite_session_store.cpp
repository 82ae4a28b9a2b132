// SqliteSessionStore: each operation is one transaction on the shared
// connection; blobs are encoded before the mutex is taken, so that a large
// snapshot does not hold up appends to other sessions while it is serialised.
#include "session/store/sqlite/sqlite_session_store.h"

#include <sqlite3.h>

#include <iterator>
#include <string>
#include <utility>

#include "session/records/snapshot_codec.h"
#include "session/store/sqlite/file_lock.h"
#include "session/store/sqlite/sqlite_schema.h"
#include "session/store/sqlite/sqlite_statement.h"
#include "session/store/store_contract.h"

namespace relmap::session {

struct SqliteSessionStore::Connection {
  FileLock claim;       // released last, once the database is closed
  SqliteConnection db;  // declared before the statements: they are finalised before it closes
  Statement insert_session;
  Statement select_session;
  Statement select_dimension;
  Statement list_sessions;
  Statement delete_samples;
  Statement delete_snapshot;
  Statement delete_session;
  Statement select_sample_by_request;
  Statement count_samples;
  Statement insert_sample;
  Statement select_samples;
  Statement upsert_snapshot;
  Statement select_snapshot;
  Statement increment_counters;
  Statement count_label;
  Statement record_model_summary;
  const char* synchronous_pragma;  // the configured durability, restored after a summary
};

namespace {

// The feature dimension of session `id`, which doubles as its existence check.
StatusOr<int> FeatureDimension(Statement& select_dimension, std::string_view id) {
  ResetOnExit reset(select_dimension);
  if (Status status = select_dimension.Bind(id); !status.ok()) return status;
  auto row = select_dimension.Step();
  if (!row.ok()) return row.status();
  if (!*row) return SessionNotFound(id);
  return static_cast<int>(select_dimension.Int64(0));
}

// Begins `transaction` and checks within it that session `id` exists; returns
// its feature dimension.
StatusOr<int> BeginOnSession(Transaction& transaction, bool write, Statement& select_dimension,
                             std::string_view id) {
  if (Status status = write ? transaction.BeginWrite() : transaction.BeginRead(); !status.ok()) {
    return status;
  }
  return FeatureDimension(select_dimension, id);
}

StatusOr<std::int64_t> SampleCount(Statement& count_samples, std::string_view id) {
  ResetOnExit reset(count_samples);
  if (Status status = count_samples.Bind(id); !status.ok()) return status;
  auto row = count_samples.Step();
  if (!row.ok()) return row.status();
  return count_samples.Int64(0);
}

// A session's record and counters, as LoadSession and ListSessions select them.
constexpr std::string_view kRecordColumns =
    "id, token_hash, created_unix_micros, config, cmm_variant, cmm_alpha,"
    " cmm_regularization, cmm_seed, cmm_pseudo_density, cmm_first_sample_mean,"
    " cmm_stale_weights, cmm_nearest_candidate_only, cmm_truncated_recheck,"
    " cmm_skip_likelihood_check, feature_dimension, frames_computed, interactions,"
    " COALESCE(last_used_unix_micros, created_unix_micros)";
constexpr int kRecordColumnCount = 18;

// The record in the current row of a statement that selected kRecordColumns first.
StatusOr<SessionRecord> RecordOfRow(const Statement& row) {
  SessionRecord r;
  r.id = row.Text(0);
  r.token_hash = row.Text(1);
  r.created_at = Timestamp(std::chrono::microseconds(row.Int64(2)));
  r.config = std::string(row.BlobView(3));
  const std::string variant = row.Text(4);
  auto parsed = cmm::ParseVariant(variant);
  if (!parsed.ok()) {
    return DataLossError("session " + Quoted(r.id) + " has unknown CMM variant " + Quoted(variant));
  }
  // The options not stored field by field are the variant's preset.
  r.cmm_config = cmm::CmmConfig::ForVariant(*parsed);
  r.cmm_config.alpha = row.Double(5);
  r.cmm_config.regularization = row.Double(6);
  r.cmm_config.seed = static_cast<std::uint64_t>(row.Int64(7));
  for (std::size_t k = 0; k < std::size(kPaper2018SwitchFields); ++k) {
    r.cmm_config.switches.*kPaper2018SwitchFields[k] = row.Int64(8 + static_cast<int>(k)) != 0;
  }
  r.feature_dimension = static_cast<int>(row.Int64(14));
  r.counters.frames_computed = row.Int64(15);
  r.counters.interactions = row.Int64(16);
  r.last_used = Timestamp(std::chrono::microseconds(row.Int64(17)));
  return r;
}

// What SaveSnapshot and RecordModelSummary check against: the session's feature
// dimension and stored sample count, read in the write transaction they begin.
struct StoredShape {
  int dimension = 0;
  std::int64_t samples = 0;
};
StatusOr<StoredShape> BeginWriteCountingSamples(Transaction& transaction,
                                                Statement& select_dimension,
                                                Statement& count_samples, std::string_view id) {
  auto dimension = BeginOnSession(transaction, /*write=*/true, select_dimension, id);
  if (!dimension.ok()) return dimension.status();
  auto samples = SampleCount(count_samples, id);
  if (!samples.ok()) return samples.status();
  return StoredShape{*dimension, *samples};
}

StatusOr<Statement> PrepareKeepingFirstError(sqlite3* db, std::string_view sql,
                                             Status& first_error) {
  auto statement = Statement::Prepare(db, sql);
  if (!statement.ok() && first_error.ok()) first_error = statement.status();
  return statement;
}

}  // namespace

StatusOr<std::unique_ptr<SqliteSessionStore>> SqliteSessionStore::Open(
    const std::string& path, const SqliteStoreOptions& options) {
  FileLock claim;
  if (options.exclusive) {
    auto acquired = FileLock::Acquire(path + ".lock");
    if (!acquired.ok()) {
      if (acquired.status().code() != StatusCode::kFailedPrecondition) return acquired.status();
      return FailedPreconditionError(Quoted(path) + " is in use by another server (it holds " +
                                     path + ".lock); one store file serves one server");
    }
    claim = std::move(acquired).value();
  }
  sqlite3* raw = nullptr;
  // NOMUTEX: the store's own mutex already serialises every use of the
  // connection, so SQLite's per-call locking would be paid for nothing.
  const int rc =
      sqlite3_open_v2(path.c_str(), &raw,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr);
  SqliteConnection db(raw);  // sqlite3_open_v2 allocates a handle even when it fails
  if (rc != SQLITE_OK) return SqliteError(db.get(), rc, "opening " + Quoted(path));
  sqlite3_extended_result_codes(db.get(), 1);
  sqlite3_busy_timeout(db.get(), static_cast<int>(options.busy_timeout.count()));

  // journal_mode answers with the mode in force; anything but "wal" (an
  // in-memory database, a file system without shared memory) loses WAL's
  // guarantees, so it is refused rather than silently accepted.
  auto mode = Statement::Prepare(db.get(), "PRAGMA journal_mode=WAL");
  if (!mode.ok()) return mode.status();
  auto row = mode->Step();
  if (!row.ok()) return row.status();
  const std::string journal_mode = *row ? mode->Text(0) : std::string();
  mode->Reset();
  if (journal_mode != "wal") {
    return FailedPreconditionError(Quoted(path) + " cannot use WAL (journal_mode is " +
                                   Quoted(journal_mode) + ")");
  }
  const bool full = options.synchronous == SqliteStoreOptions::Synchronous::kFull;
  const char* synchronous_pragma = full ? "PRAGMA synchronous=FULL" : "PRAGMA synchronous=NORMAL";
  if (Status status = Execute(db.get(), synchronous_pragma); !status.ok()) return status;
  if (Status status = Execute(db.get(), "PRAGMA foreign_keys=ON"); !status.ok()) return status;
  if (Status status = MigrateSchema(db.get()); !status.ok()) return status;

  sqlite3* h = db.get();
  Status error;
  auto prepare = [&](std::string_view sql) { return PrepareKeepingFirstError(h, sql, error); };
  auto insert_session = prepare(
      "INSERT INTO sessions (id, token_hash, created_unix_micros, config, cmm_variant, cmm_alpha,"
      " cmm_regularization, cmm_seed, cmm_pseudo_density, cmm_first_sample_mean,"
      " cmm_stale_weights, cmm_nearest_candidate_only, cmm_truncated_recheck,"
      " cmm_skip_likelihood_check, feature_dimension)"
      " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15)");
  auto select_session =
      prepare("SELECT " + std::string(kRecordColumns) + " FROM sessions WHERE id = ?1");
  auto select_dimension = prepare("SELECT feature_dimension FROM sessions WHERE id = ?1");
  auto list_sessions = prepare("SELECT " + std::string(kRecordColumns) +
                               ", samples_non_moveable, samples_moveable, model_sample_count,"
                               " model_components_non_moveable, model_components_moveable"
                               " FROM sessions ORDER BY id");
  auto delete_samples = prepare("DELETE FROM samples WHERE session_id = ?1");
  auto delete_snapshot = prepare("DELETE FROM snapshots WHERE session_id = ?1");
  auto delete_session = prepare("DELETE FROM sessions WHERE id = ?1");
  auto select_sample_by_request = prepare(
      "SELECT sequence, features, label FROM samples WHERE session_id = ?1 AND request_id = ?2");
  // Sequence numbers have no gaps, so the next number is also the sample count;
  // MAX is one step down the (session_id, sequence) key, where COUNT(*) would
  // scan every sample of the session.
  auto count_samples =
      prepare("SELECT COALESCE(MAX(sequence) + 1, 0) FROM samples WHERE session_id = ?1");
  auto insert_sample = prepare(
      "INSERT INTO samples (session_id, sequence, request_id, features, label)"
      " VALUES (?1, ?2, ?3, ?4, ?5)");
  auto select_samples = prepare(
      "SELECT sequence, request_id, features, label FROM samples WHERE session_id = ?1"
      " ORDER BY sequence");
  auto upsert_snapshot = prepare(
      "INSERT INTO snapshots (session_id, sample_count, snapshot) VALUES (?1, ?2, ?3)"
      " ON CONFLICT (session_id) DO UPDATE SET sample_count = excluded.sample_count,"
      " snapshot = excluded.snapshot");
  auto select_snapshot =
      prepare("SELECT sample_count, snapshot FROM snapshots WHERE session_id = ?1");
  auto increment_counters = prepare(
      "UPDATE sessions SET frames_computed = frames_computed + ?2,"
      " interactions = interactions + ?3 WHERE id = ?1");
  // In AppendSample's transaction, so that the counts are the stored samples'.
  auto count_label = prepare(
      "UPDATE sessions SET samples_non_moveable = samples_non_moveable + (?2 = 0),"
      " samples_moveable = samples_moveable + (?2 = 1) WHERE id = ?1");
  auto record_model_summary = prepare(
      "UPDATE sessions SET model_sample_count = ?2, model_components_non_moveable = ?3,"
      " model_components_moveable = ?4, last_used_unix_micros = ?5"
      " WHERE id = ?1 AND (model_sample_count IS NULL OR model_sample_count < ?2"
      " OR (model_sample_count = ?2 AND last_used_unix_micros <= ?5))");
  if (!error.ok()) return error;

  // Not make_unique: Connection is an aggregate, which make_unique builds with
  // parentheses, and clang before 16 (clang-tidy's parser here) cannot.
  auto connection = std::unique_ptr<Connection>(  // NOLINT(modernize-make-unique)
      new Connection{std::move(claim), std::move(db), std::move(insert_session).value(),
                     std::move(select_session).value(), std::move(select_dimension).value(),
                     std::move(list_sessions).value(), std::move(delete_samples).value(),
                     std::move(delete_snapshot).value(), std::move(delete_session).value(),
                     std::move(select_sample_by_request).value(), std::move(count_samples).value(),
                     std::move(insert_sample).value(), std::move(select_samples).value(),
                     std::move(upsert_snapshot).value(), std::move(select_snapshot).value(),
                     std::move(increment_counters).value(), std::move(count_label).value(),
                     std::move(record_model_summary).value(), synchronous_pragma});
  return std::unique_ptr<SqliteSessionStore>(new SqliteSessionStore(std::move(connection)));
}

SqliteSessionStore::SqliteSessionStore(std::unique_ptr<Connection> connection)
    : connection_(std::move(connection)) {}

SqliteSessionStore::~SqliteSessionStore() = default;

Status SqliteSessionStore::CreateSession(const SessionRecord& r) {
  if (Status status = CheckRecord(r); !status.ok()) return status;
  const cmm::Paper2018Switches& s = r.cmm_config.switches;
  static_assert(std::size(kPaper2018SwitchFields) == 6, "a new switch needs a column and a bind");
  const auto flag = [](bool b) { return static_cast<std::int64_t>(b); };

  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  Transaction transaction(c.db.get());
  if (Status status = transaction.BeginWrite(); !status.ok()) return status;
  if (auto dimension = FeatureDimension(c.select_dimension, r.id); dimension.ok()) {
    return {StatusCode::kAlreadyExists, "session " + Quoted(r.id) + " already exists"};
  } else if (dimension.status().code() != StatusCode::kNotFound) {
    return dimension.status();
  }
  ResetOnExit reset(c.insert_session);
  if (Status status = c.insert_session.Bind(
          std::string_view(r.id), std::string_view(r.token_hash),
          static_cast<std::int64_t>(r.created_at.time_since_epoch().count()), Blob{r.config},
          cmm::VariantName(r.cmm_config.variant), r.cmm_config.alpha, r.cmm_config.regularization,
          static_cast<std::int64_t>(r.cmm_config.seed), flag(s.pseudo_density),
          flag(s.first_sample_mean), flag(s.stale_weights), flag(s.nearest_candidate_only),
          flag(s.truncated_recheck), flag(s.skip_likelihood_check),
          static_cast<std::int64_t>(r.feature_dimension));
      !status.ok()) {
    return status;
  }
  if (Status status = c.insert_session.Run(); !status.ok()) return status;
  return transaction.Commit();
}

StatusOr<SessionRecord> SqliteSessionStore::LoadSession(std::string_view id) {
  std::lock_guard lock(mutex_);
  Statement& select = connection_->select_session;
  ResetOnExit reset(select);
  if (Status status = select.Bind(id); !status.ok()) return status;
  auto row = select.Step();
  if (!row.ok()) return row.status();
  if (!*row) return SessionNotFound(id);
  return RecordOfRow(select);
}

StatusOr<std::vector<SessionSummary>> SqliteSessionStore::ListSessions() {
  std::lock_guard lock(mutex_);
  Statement& list = connection_->list_sessions;
  ResetOnExit reset(list);
  if (Status status = list.Bind(); !status.ok()) return status;
  std::vector<SessionSummary> sessions;
  while (true) {
    auto row = list.Step();
    if (!row.ok()) return row.status();
    if (!*row) break;
    auto record = RecordOfRow(list);
    if (!record.ok()) return record.status();
    SessionSummary summary;
    summary.record = std::move(record).value();
    constexpr int k = kRecordColumnCount;
    summary.samples[0] = list.Int64(k);
    summary.samples[1] = list.Int64(k + 1);
    if (!list.IsNull(k + 2)) {
      summary.model = ModelSummary{
          list.Int64(k + 2), {list.Int64(k + 3), list.Int64(k + 4)}, summary.record.last_used};
    }
    sessions.push_back(std::move(summary));
  }
  return sessions;
}

Status SqliteSessionStore::DeleteSession(std::string_view id) {
  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  Transaction transaction(c.db.get());
  if (Status status = transaction.BeginWrite(); !status.ok()) return status;
  // Children first: the foreign keys refuse a session row that samples still name.
  for (Statement* statement : {&c.delete_samples, &c.delete_snapshot, &c.delete_session}) {
    ResetOnExit reset(*statement);
    if (Status status = statement->Bind(id); !status.ok()) return status;
    if (Status status = statement->Run(); !status.ok()) return status;
  }
  if (sqlite3_changes(c.db.get()) == 0) return SessionNotFound(id);
  return transaction.Commit();
}

StatusOr<std::int64_t> SqliteSessionStore::AppendSample(std::string_view session_id,
                                                        std::string_view request_id,
                                                        std::span<const double> features,
                                                        int label) {
  if (Status status = CheckSample(request_id, features, label); !status.ok()) return status;
  const std::string blob = EncodeFeatures(features);

  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  Transaction transaction(c.db.get());
  auto dimension = BeginOnSession(transaction, /*write=*/true, c.select_dimension, session_id);
  if (!dimension.ok()) return dimension.status();
  if (Status status = CheckFeatureCount(session_id, features, *dimension); !status.ok()) {
    return status;
  }

  {
    // A retried request: answer as the first time, without a second row. The
    // first commit was durable, so there is nothing to commit now.
    Statement& existing = c.select_sample_by_request;
    ResetOnExit reset(existing);
    if (Status status = existing.Bind(session_id, request_id); !status.ok()) return status;
    auto row = existing.Step();
    if (!row.ok()) return row.status();
    if (*row) {
      if (existing.BlobView(1) != blob || existing.Int64(2) != label) {
        return RequestIdReused(session_id, request_id);
      }
      return existing.Int64(0);
    }
  }

  auto sequence = SampleCount(c.count_samples, session_id);
  if (!sequence.ok()) return sequence.status();
  ResetOnExit reset(c.insert_sample);
  if (Status status = c.insert_sample.Bind(session_id, *sequence, request_id, Blob{blob},
                                           static_cast<std::int64_t>(label));
      !status.ok()) {
    return status;
  }
  if (Status status = c.insert_sample.Run(); !status.ok()) return status;
  ResetOnExit reset_count(c.count_label);
  if (Status status = c.count_label.Bind(session_id, static_cast<std::int64_t>(label));
      !status.ok()) {
    return status;
  }
  if (Status status = c.count_label.Run(); !status.ok()) return status;
  if (Status status = transaction.Commit(); !status.ok()) return status;
  return *sequence;
}

StatusOr<std::vector<StoredSample>> SqliteSessionStore::LoadSamples(std::string_view session_id) {
  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  // One read transaction: the existence check and the rows see the same state.
  Transaction transaction(c.db.get());
  auto dimension = BeginOnSession(transaction, /*write=*/false, c.select_dimension, session_id);
  if (!dimension.ok()) return dimension.status();

  Statement& select = c.select_samples;
  ResetOnExit reset(select);
  if (Status status = select.Bind(session_id); !status.ok()) return status;
  std::vector<StoredSample> samples;
  while (true) {
    auto row = select.Step();
    if (!row.ok()) return row.status();
    if (!*row) break;
    StoredSample sample;
    sample.sequence = select.Int64(0);
    sample.request_id = select.Text(1);
    auto features = DecodeFeatures(select.BlobView(2), *dimension, session_id, sample.sequence);
    if (!features.ok()) return features.status();
    sample.features = std::move(features).value();
    sample.label = static_cast<int>(select.Int64(3));
    samples.push_back(std::move(sample));
  }
  return samples;
}

Status SqliteSessionStore::SaveSnapshot(std::string_view session_id,
                                        const cmm::CmmSnapshot& snapshot,
                                        std::int64_t sample_count) {
  if (Status status = CheckSnapshotSampleCount(sample_count); !status.ok()) return status;
  auto blob = EncodeSnapshot(snapshot);
  if (!blob.ok()) return blob.status();

  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  Transaction transaction(c.db.get());
  auto stored =
      BeginWriteCountingSamples(transaction, c.select_dimension, c.count_samples, session_id);
  if (!stored.ok()) return stored.status();
  if (Status status = CheckSnapshotAgainstSession(session_id, snapshot, sample_count,
                                                  stored->dimension, stored->samples);
      !status.ok()) {
    return status;
  }
  ResetOnExit reset(c.upsert_snapshot);
  if (Status status = c.upsert_snapshot.Bind(session_id, sample_count, Blob{*blob}); !status.ok()) {
    return status;
  }
  if (Status status = c.upsert_snapshot.Run(); !status.ok()) return status;
  return transaction.Commit();
}

StatusOr<std::optional<StoredSnapshot>> SqliteSessionStore::LoadLatestSnapshot(
    std::string_view session_id) {
  std::string blob;
  std::int64_t sample_count = 0;
  {
    std::lock_guard lock(mutex_);
    Connection& c = *connection_;
    Transaction transaction(c.db.get());
    auto dimension = BeginOnSession(transaction, /*write=*/false, c.select_dimension, session_id);
    if (!dimension.ok()) return dimension.status();
    Statement& select = c.select_snapshot;
    ResetOnExit reset(select);
    if (Status status = select.Bind(session_id); !status.ok()) return status;
    auto row = select.Step();
    if (!row.ok()) return row.status();
    if (!*row) return std::optional<StoredSnapshot>();
    sample_count = select.Int64(0);
    blob = std::string(select.BlobView(1));
  }
  // Decoding (and its checksum) runs outside the lock, like encoding.
  auto snapshot = DecodeSnapshot(blob);
  if (!snapshot.ok()) {
    return SnapshotDecodeError(session_id, snapshot.status());
  }
  return std::optional<StoredSnapshot>(StoredSnapshot{std::move(snapshot).value(), sample_count});
}

Status SqliteSessionStore::IncrementCounters(std::string_view session_id,
                                             const SessionCounters& delta) {
  if (Status status = CheckCounterDelta(delta); !status.ok()) return status;
  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  ResetOnExit reset(c.increment_counters);
  if (Status status =
          c.increment_counters.Bind(session_id, delta.frames_computed, delta.interactions);
      !status.ok()) {
    return status;
  }
  if (Status status = c.increment_counters.Run(); !status.ok()) return status;
  if (sqlite3_changes(c.db.get()) == 0) return SessionNotFound(session_id);
  return OkStatus();
}

Status SqliteSessionStore::RecordModelSummary(std::string_view session_id,
                                              const ModelSummary& summary) {
  if (Status status = CheckModelSummary(summary); !status.ok()) return status;
  std::lock_guard lock(mutex_);
  Connection& c = *connection_;
  // A summary only saves loading a session to list it, and the samples determine it: its
  // commit need not wait for the disk (a power loss may undo it, never tear it; a later
  // durable commit syncs it too). With synchronous=FULL, waiting would double the fsyncs
  // of a one-sample call.
  if (Status status = Execute(c.db.get(), "PRAGMA synchronous=OFF"); !status.ok()) return status;
  struct RestoreDurability {
    Connection& c;
    ~RestoreDurability() { (void)Execute(c.db.get(), c.synchronous_pragma); }
  } restore_durability{c};
  Transaction transaction(c.db.get());
  auto stored =
      BeginWriteCountingSamples(transaction, c.select_dimension, c.count_samples, session_id);
  if (!stored.ok()) return stored.status();
  if (Status status = CheckModelSummaryAgainstSession(session_id, summary, stored->samples);
      !status.ok()) {
    return status;
  }
  ResetOnExit reset(c.record_model_summary);
  if (Status status = c.record_model_summary.Bind(
          session_id, summary.sample_count, summary.components[0], summary.components[1],
          static_cast<std::int64_t>(summary.last_used.time_since_epoch().count()));
      !status.ok()) {
    return status;
  }
  if (Status status = c.record_model_summary.Run(); !status.ok()) return status;
  return transaction.Commit();
}

}  // namespace relmap::session
