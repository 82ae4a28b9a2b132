// RAII ownership of a SQLite connection and its prepared statements, and the
// translation of SQLite result codes into relmap Status values.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::session {

struct SqliteCloser {
  void operator()(sqlite3* db) const { sqlite3_close_v2(db); }
};
using SqliteConnection = std::unique_ptr<sqlite3, SqliteCloser>;

// `what` failed with result code `rc`: a Status whose code says whether to retry
// (busy, I/O → UNAVAILABLE), the file is damaged (→ DATA_LOSS), the disk is full
// (→ RESOURCE_EXHAUSTED) or the store has a bug (→ INTERNAL), and whose message
// carries sqlite3_errmsg. Call it before anything else touches the connection.
Status SqliteError(sqlite3* db, int rc, std::string_view what);

// Runs `sql` (one or more statements, no parameters, rows discarded).
Status Execute(sqlite3* db, std::string_view sql);

// A BLOB parameter or column, as opposed to TEXT.
struct Blob {
  std::string_view bytes;
};

// A prepared statement, compiled once and run many times. Not thread-safe: the
// connection's owner serialises its use.
class Statement {
 public:
  static StatusOr<Statement> Prepare(sqlite3* db, std::string_view sql);

  // Resets the statement and binds args to ?1..?N: std::string_view (TEXT),
  // Blob, std::int64_t or double. Text and blobs are bound without a copy, so
  // they must outlive the run (ResetOnExit unbinds them).
  template <typename... Args>
  Status Bind(const Args&... args) {
    Reset();
    int index = 0;
    Status status;
    (void)(... && (status = BindOne(++index, args)).ok());
    return status;
  }

  // Steps once: true if a row is ready to read, false when the statement is done.
  StatusOr<bool> Step();
  // Steps to the end of a statement that returns no row.
  Status Run();

  bool IsNull(int column) const { return sqlite3_column_type(stmt_.get(), column) == SQLITE_NULL; }
  std::int64_t Int64(int column) const { return sqlite3_column_int64(stmt_.get(), column); }
  double Double(int column) const { return sqlite3_column_double(stmt_.get(), column); }
  std::string Text(int column) const;
  // Valid until the next Step or Reset.
  std::string_view BlobView(int column) const;

  // Returns the statement to its initial state and drops its bindings, so that
  // it holds no read snapshot and no pointer into the caller's data.
  void Reset();

 private:
  struct Finalizer {
    void operator()(sqlite3_stmt* stmt) const { sqlite3_finalize(stmt); }
  };
  Statement(sqlite3* db, sqlite3_stmt* stmt, std::string_view sql)
      : db_(db), stmt_(stmt), sql_(sql) {}

  Status BindOne(int index, std::string_view text);
  Status BindOne(int index, Blob blob);
  Status BindOne(int index, std::int64_t value);
  Status BindOne(int index, double value);
  Status Check(int rc, std::string_view what) const;

  sqlite3* db_;
  std::unique_ptr<sqlite3_stmt, Finalizer> stmt_;
  std::string sql_;  // for error messages
};

// Resets a statement when leaving the scope that used it, on every path.
class ResetOnExit {
 public:
  explicit ResetOnExit(Statement& statement) : statement_(statement) {}
  ~ResetOnExit() { statement_.Reset(); }
  ResetOnExit(const ResetOnExit&) = delete;
  ResetOnExit& operator=(const ResetOnExit&) = delete;

 private:
  Statement& statement_;
};

// A transaction that rolls back on destruction unless Commit succeeded.
class Transaction {
 public:
  explicit Transaction(sqlite3* db) : db_(db) {}
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  // BEGIN: several reads see one consistent state of the database.
  Status BeginRead();
  // BEGIN IMMEDIATE takes the write lock up front, so a transaction that reads
  // then writes never fails halfway with SQLITE_BUSY on the lock upgrade (which
  // the busy timeout cannot wait out).
  Status BeginWrite();
  // With synchronous=FULL, returns once the commit is on stable storage.
  Status Commit();

 private:
  sqlite3* db_;
  bool open_ = false;
};

}  // namespace relmap::session
