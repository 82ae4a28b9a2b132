// SQLite result codes to Status, prepared statements and write transactions.
#include "session/store/sqlite/sqlite_statement.h"

#include <limits>
#include <utility>

namespace relmap::session {

Status SqliteError(sqlite3* db, int rc, std::string_view what) {
  StatusCode code = StatusCode::kInternal;
  switch (rc & 0xFF) {  // the primary code of an extended result code
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
    case SQLITE_IOERR:
    case SQLITE_CANTOPEN:
      code = StatusCode::kUnavailable;
      break;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      code = StatusCode::kDataLoss;
      break;
    case SQLITE_FULL:
      code = StatusCode::kResourceExhausted;
      break;
    case SQLITE_READONLY:
    case SQLITE_PERM:
      code = StatusCode::kFailedPrecondition;
      break;
    default:
      break;
  }
  // sqlite3_errmsg names the last failure on the connection; sqlite3_errstr is
  // the fallback when there is no connection (open failed to allocate one).
  const char* detail = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  return {code, std::string(what) + ": " + detail + " (sqlite code " + std::to_string(rc) + ")"};
}

Status Execute(sqlite3* db, std::string_view sql) {
  const std::string script(sql);  // sqlite3_exec wants a NUL-terminated string
  const int rc = sqlite3_exec(db, script.c_str(), nullptr, nullptr, nullptr);
  if (rc != SQLITE_OK) return SqliteError(db, rc, "executing \"" + script + "\"");
  return OkStatus();
}

StatusOr<Statement> Statement::Prepare(sqlite3* db, std::string_view sql) {
  sqlite3_stmt* stmt = nullptr;
  const int rc = sqlite3_prepare_v3(db, sql.data(), static_cast<int>(sql.size()),
                                    SQLITE_PREPARE_PERSISTENT, &stmt, nullptr);
  if (rc != SQLITE_OK) {
    sqlite3_finalize(stmt);
    return SqliteError(db, rc, "preparing \"" + std::string(sql) + "\"");
  }
  return Statement(db, stmt, sql);
}

StatusOr<bool> Statement::Step() {
  const int rc = sqlite3_step(stmt_.get());
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  return Check(rc, "running");
}

Status Statement::Run() {
  auto row = Step();
  if (!row.ok()) return row.status();
  if (*row) return InternalError("\"" + sql_ + "\" returned a row where none was expected");
  return OkStatus();
}

std::string Statement::Text(int column) const {
  const auto* text = sqlite3_column_text(stmt_.get(), column);
  // The byte count is asked after the text, as SQLite's documentation requires.
  const int bytes = sqlite3_column_bytes(stmt_.get(), column);
  return text == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(text), bytes);
}

std::string_view Statement::BlobView(int column) const {
  const void* data = sqlite3_column_blob(stmt_.get(), column);
  const int bytes = sqlite3_column_bytes(stmt_.get(), column);
  return data == nullptr ? std::string_view()
                         : std::string_view(static_cast<const char*>(data), bytes);
}

void Statement::Reset() {
  // sqlite3_reset repeats the last step's error, which was reported already.
  sqlite3_reset(stmt_.get());
  sqlite3_clear_bindings(stmt_.get());
}

Status Statement::BindOne(int index, std::string_view text) {
  // A null pointer would bind NULL, not an empty string.
  const char* data = text.empty() ? "" : text.data();
  return Check(
      sqlite3_bind_text64(stmt_.get(), index, data, text.size(), SQLITE_STATIC, SQLITE_UTF8),
      "binding text");
}

Status Statement::BindOne(int index, Blob blob) {
  if (blob.bytes.empty())
    return Check(sqlite3_bind_zeroblob(stmt_.get(), index, 0), "binding blob");
  return Check(
      sqlite3_bind_blob64(stmt_.get(), index, blob.bytes.data(), blob.bytes.size(), SQLITE_STATIC),
      "binding blob");
}

Status Statement::BindOne(int index, std::int64_t value) {
  return Check(sqlite3_bind_int64(stmt_.get(), index, value), "binding integer");
}

Status Statement::BindOne(int index, double value) {
  return Check(sqlite3_bind_double(stmt_.get(), index, value), "binding real");
}

Status Statement::Check(int rc, std::string_view what) const {
  if (rc == SQLITE_OK) return OkStatus();
  return SqliteError(db_, rc, std::string(what) + " in \"" + sql_ + "\"");
}

Transaction::~Transaction() {
  // Nothing to report a failed rollback to; SQLite rolls back an interrupted
  // transaction on the next open anyway.
  if (open_) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

Status Transaction::BeginRead() {
  if (Status status = Execute(db_, "BEGIN"); !status.ok()) return status;
  open_ = true;
  return OkStatus();
}

Status Transaction::BeginWrite() {
  if (Status status = Execute(db_, "BEGIN IMMEDIATE"); !status.ok()) return status;
  open_ = true;
  return OkStatus();
}

Status Transaction::Commit() {
  if (Status status = Execute(db_, "COMMIT"); !status.ok()) return status;
  open_ = false;
  return OkStatus();
}

}  // namespace relmap::session
