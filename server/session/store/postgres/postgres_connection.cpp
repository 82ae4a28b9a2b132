// libpq wrappers. Every statement is sent with PQexecParams and binary results,
// so that no value goes through a text conversion on its way in or out.
#include "session/store/postgres/postgres_connection.h"

#include <bit>
#include <cstring>
#include <utility>

namespace relmap::session {
namespace {

// Type OIDs of the built-in types (catalog/pg_type.dat; fixed since 7.x).
constexpr Oid kBoolOid = 16;
constexpr Oid kByteaOid = 17;
constexpr Oid kInt8Oid = 20;
constexpr Oid kInt4Oid = 23;
constexpr Oid kTextOid = 25;
constexpr Oid kFloat8Oid = 701;

constexpr int kBinary = 1;

// Big-endian (network order) bytes of an unsigned integer, as the binary
// format wants them.
std::string BigEndian(std::uint64_t value, int bytes) {
  std::string out(static_cast<std::size_t>(bytes), '\0');
  for (int i = 0; i < bytes; ++i) {
    out[static_cast<std::size_t>(bytes - 1 - i)] = static_cast<char>((value >> (8 * i)) & 0xFFu);
  }
  return out;
}

std::uint64_t FromBigEndian(std::string_view bytes) {
  std::uint64_t value = 0;
  for (char c : bytes) value = (value << 8) | static_cast<unsigned char>(c);
  return value;
}

// libpq's messages end in a newline.
std::string Trimmed(const char* message) {
  std::string text = message != nullptr ? message : "";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

// The code for an error of SQLSTATE `state` (Appendix A of the PostgreSQL
// manual): what the caller should do about it.
StatusCode CodeOfSqlState(std::string_view state) {
  const std::string_view sql_class = state.substr(0, 2);
  // Connection exception, operator intervention (shutdown, termination), lack of
  // resources: the database, not the request, is the problem; retry later.
  if (sql_class == "08" || sql_class == "57" || sql_class == "53") return StatusCode::kUnavailable;
  // Serialisation failure, deadlock: retry the transaction.
  if (sql_class == "40") return StatusCode::kAborted;
  if (state == "55P03") return StatusCode::kUnavailable;  // lock not available
  // Text that is not valid UTF-8 or holds a NUL byte.
  if (state == "22021" || state == "22P05") return StatusCode::kInvalidArgument;
  if (state == "23505") return StatusCode::kAlreadyExists;
  return StatusCode::kInternal;
}

}  // namespace

std::string_view PgResult::Bytes(int row, int column) const {
  return {PQgetvalue(result_.get(), row, column),
          static_cast<std::size_t>(PQgetlength(result_.get(), row, column))};
}

bool PgResult::Bool(int row, int column) const {
  const std::string_view bytes = Bytes(row, column);
  return !bytes.empty() && bytes[0] != 0;
}

std::int32_t PgResult::Int4(int row, int column) const {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(FromBigEndian(Bytes(row, column))));
}

std::int64_t PgResult::Int8(int row, int column) const {
  return static_cast<std::int64_t>(FromBigEndian(Bytes(row, column)));
}

double PgResult::Float8(int row, int column) const {
  return std::bit_cast<double>(FromBigEndian(Bytes(row, column)));
}

std::int64_t PgResult::AffectedRows() const {
  const char* tuples = PQcmdTuples(result_.get());
  return tuples[0] == '\0' ? 0 : std::stoll(tuples);
}

PgParams& PgParams::Add(Oid type, const char* data, std::size_t length) {
  types_.push_back(type);
  // A null pointer would be SQL NULL: an empty value needs a real address.
  values_.push_back(data != nullptr ? data : "");
  lengths_.push_back(static_cast<int>(length));
  formats_.push_back(kBinary);
  return *this;
}

PgParams& PgParams::AddOwned(Oid type, std::string bytes) {
  const std::string& stored = owned_.emplace_back(std::move(bytes));
  return Add(type, stored.data(), stored.size());
}

PgParams& PgParams::Text(std::string_view text) { return Add(kTextOid, text.data(), text.size()); }
PgParams& PgParams::Bytea(std::string_view bytes) {
  return Add(kByteaOid, bytes.data(), bytes.size());
}
PgParams& PgParams::Bool(bool value) { return AddOwned(kBoolOid, std::string(1, value ? 1 : 0)); }
PgParams& PgParams::Int4(std::int32_t value) {
  return AddOwned(kInt4Oid, BigEndian(static_cast<std::uint32_t>(value), 4));
}
PgParams& PgParams::Int8(std::int64_t value) {
  return AddOwned(kInt8Oid, BigEndian(static_cast<std::uint64_t>(value), 8));
}
PgParams& PgParams::Float8(double value) {
  return AddOwned(kFloat8Oid, BigEndian(std::bit_cast<std::uint64_t>(value), 8));
}

namespace {

PGconn* ConnectRaw(const PgConnectionSettings& settings) {
  const std::string timeout_text = std::to_string(settings.connect_timeout.count());
  // expand_dbname: `dbname` may be a whole URI or key=value string; the
  // parameters after it override what it says.
  const char* keywords[] = {"dbname", "application_name", "connect_timeout", "client_encoding",
                            nullptr};
  const char* values[] = {settings.conninfo.c_str(), settings.application_name.c_str(),
                          timeout_text.c_str(), "UTF8", nullptr};
  PGconn* conn = PQconnectdbParams(keywords, values, /*expand_dbname=*/1);
  // libpq prints NOTICEs (CREATE TABLE IF NOT EXISTS of an existing table...) on
  // stderr; the store reports through its statuses only.
  if (conn != nullptr)
    PQsetNoticeProcessor(
        conn, [](void*, const char*) {}, nullptr);
  return conn;
}

}  // namespace

Status PgConnection::Configure() {
  // A commit is acknowledged only once it is on the server's disk. A database
  // configured with synchronous_commit = off would acknowledge before; raise it
  // to local, and keep any stronger setting (on, remote_write, remote_apply).
  const std::string lock_timeout = std::to_string(settings_.lock_timeout.count());
  auto configured = Execute(
      "SELECT set_config('synchronous_commit', 'local', false)"
      " WHERE current_setting('synchronous_commit') = 'off'"
      " UNION ALL SELECT set_config('lock_timeout', $1, false)"
      " UNION ALL SELECT set_config('idle_in_transaction_session_timeout', $1, false)",
      PgParams().Text(lock_timeout), "configuring the connection");
  return configured.status();
}

StatusOr<std::unique_ptr<PgConnection>> PgConnection::Connect(
    const PgConnectionSettings& settings) {
  PGconn* conn = ConnectRaw(settings);
  if (conn == nullptr) return Status(StatusCode::kUnavailable, "PostgreSQL: out of memory");
  std::unique_ptr<PgConnection> connection(new PgConnection(conn, settings));
  if (PQstatus(conn) != CONNECTION_OK) {
    return Status(StatusCode::kUnavailable,
                  "cannot connect to PostgreSQL: " + Trimmed(PQerrorMessage(conn)));
  }
  if (Status status = connection->Configure(); !status.ok()) return status;
  return connection;
}

PgConnection::~PgConnection() { PQfinish(conn_); }

Status PgConnection::Reconnect() {
  PQfinish(conn_);
  conn_ = ConnectRaw(settings_);
  if (conn_ == nullptr || PQstatus(conn_) != CONNECTION_OK) {
    return Status(StatusCode::kUnavailable,
                  "cannot reconnect to PostgreSQL: " +
                      Trimmed(conn_ != nullptr ? PQerrorMessage(conn_) : "out of memory"));
  }
  return Configure();
}

Status PgConnection::ErrorOf(const PGresult* result, std::string_view what) const {
  const char* state = result != nullptr ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  const char* primary =
      result != nullptr ? PQresultErrorField(result, PG_DIAG_MESSAGE_PRIMARY) : nullptr;
  std::string message = std::string(what).append(": ");
  if (state == nullptr || PQstatus(conn_) != CONNECTION_OK) {
    // No SQLSTATE: libpq itself failed, which means the connection did.
    message.append("lost the connection to PostgreSQL: ").append(Trimmed(PQerrorMessage(conn_)));
    return {StatusCode::kUnavailable, message};
  }
  message.append("PostgreSQL: ")
      .append(primary != nullptr ? primary : Trimmed(PQerrorMessage(conn_)))
      .append(" (SQLSTATE ")
      .append(state)
      .append(")");
  return {CodeOfSqlState(state), message};
}

StatusOr<PgResult> PgConnection::Execute(std::string_view sql, const PgParams& params,
                                         std::string_view what) {
  const std::string text(sql);
  PgResult result(PQexecParams(conn_, text.c_str(), params.size(), params.types(), params.values(),
                               params.lengths(), params.formats(), kBinary));
  const ExecStatusType status = PQresultStatus(result.get());
  if (result.get() == nullptr || (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)) {
    return ErrorOf(result.get(), what);
  }
  return result;
}

StatusOr<PgResult> PgConnection::ExecuteRetryingOnce(std::string_view sql, const PgParams& params,
                                                     std::string_view what) {
  auto result = Execute(sql, params, what);
  if (result.ok() || healthy()) return result;
  if (Status reconnected = Reconnect(); !reconnected.ok()) return reconnected;
  return Execute(sql, params, what);
}

Status PgConnection::ExecuteScript(std::string_view sql, std::string_view what) {
  const std::string text(sql);
  PgResult result(PQexec(conn_, text.c_str()));
  const ExecStatusType status = PQresultStatus(result.get());
  if (result.get() == nullptr || (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)) {
    return ErrorOf(result.get(), what);
  }
  return OkStatus();
}

PgTransaction::~PgTransaction() {
  if (open_ && connection_.healthy()) {
    // Best effort: a connection that fails here is replaced by the pool, and the
    // server rolls back what a lost connection left open.
    (void)connection_.ExecuteScript("ROLLBACK", "rolling back");
  }
}

Status PgTransaction::Begin() {
  Status status = connection_.ExecuteScript("BEGIN", "beginning a transaction");
  if (!status.ok() && !connection_.healthy()) {
    if (Status reconnected = connection_.Reconnect(); !reconnected.ok()) return reconnected;
    status = connection_.ExecuteScript("BEGIN", "beginning a transaction");
  }
  open_ = status.ok();
  return status;
}

Status PgTransaction::Commit() {
  auto result = connection_.Execute("COMMIT", {}, "committing");
  open_ = false;
  if (!result.ok()) return result.status();
  // COMMIT of a transaction that failed earlier answers ROLLBACK, not an error.
  if (std::strcmp(PQcmdStatus(const_cast<PGresult*>(result->get())), "COMMIT") != 0) {
    return {StatusCode::kAborted, "the transaction was rolled back, not committed"};
  }
  return OkStatus();
}

PostgresConnectionPool::~PostgresConnectionPool() = default;

PostgresConnectionPool::Lease::~Lease() {
  if (pool_ != nullptr && connection_ != nullptr) pool_->Return(std::move(connection_));
}

StatusOr<PostgresConnectionPool::Lease> PostgresConnectionPool::Take() {
  std::unique_ptr<PgConnection> connection;
  {
    std::unique_lock lock(mutex_);
    returned_.wait(lock, [&] { return !idle_.empty() || free_slots_ > 0; });
    if (!idle_.empty()) {
      connection = std::move(idle_.back());
      idle_.pop_back();
    } else {
      --free_slots_;
    }
  }
  // Connecting happens outside the lock: it may take up to the connect timeout.
  Status status;
  if (connection == nullptr) {
    auto opened = PgConnection::Connect(settings_);
    if (opened.ok()) {
      connection = std::move(opened).value();
    } else {
      status = opened.status();
    }
  } else if (!connection->healthy()) {
    status = connection->Reconnect();
  }
  if (!status.ok()) {
    {
      std::lock_guard lock(mutex_);
      ++free_slots_;
    }
    returned_.notify_one();
    return status;
  }
  return Lease(this, std::move(connection));
}

void PostgresConnectionPool::Return(std::unique_ptr<PgConnection> connection) {
  {
    std::lock_guard lock(mutex_);
    idle_.push_back(std::move(connection));
  }
  returned_.notify_one();
}

}  // namespace relmap::session
