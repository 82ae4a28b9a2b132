// libpq under RAII: a connection, its results, binary parameters, transactions
// and a small pool, with PostgreSQL's errors translated into relmap Status values.
#pragma once

#include <libpq-fe.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"

namespace relmap::session {

// The result of one statement, read in PostgreSQL's binary format: integers and
// doubles as their exact bits, text and bytea as their bytes.
class PgResult {
 public:
  explicit PgResult(PGresult* result) : result_(result) {}

  int rows() const { return PQntuples(result_.get()); }
  bool IsNull(int row, int column) const { return PQgetisnull(result_.get(), row, column) != 0; }
  // Valid as long as the result.
  std::string_view Bytes(int row, int column) const;
  std::string Text(int row, int column) const { return std::string(Bytes(row, column)); }
  bool Bool(int row, int column) const;
  std::int32_t Int4(int row, int column) const;
  std::int64_t Int8(int row, int column) const;
  double Float8(int row, int column) const;
  // The number of rows an INSERT, UPDATE or DELETE touched.
  std::int64_t AffectedRows() const;
  const PGresult* get() const { return result_.get(); }

 private:
  struct Clear {
    void operator()(PGresult* result) const { PQclear(result); }
  };
  std::unique_ptr<PGresult, Clear> result_;
};

// The parameters $1..$N of a statement, in binary format with their types
// stated. Text and bytea are not copied: they must outlive the statement's run.
class PgParams {
 public:
  PgParams& Text(std::string_view text);
  PgParams& Bytea(std::string_view bytes);
  PgParams& Bool(bool value);
  PgParams& Int4(std::int32_t value);
  PgParams& Int8(std::int64_t value);
  PgParams& Float8(double value);

  int size() const { return static_cast<int>(types_.size()); }
  const Oid* types() const { return types_.data(); }
  const char* const* values() const { return values_.data(); }
  const int* lengths() const { return lengths_.data(); }
  const int* formats() const { return formats_.data(); }

 private:
  PgParams& Add(Oid type, const char* data, std::size_t length);
  PgParams& AddOwned(Oid type, std::string bytes);

  std::vector<Oid> types_;
  std::vector<const char*> values_;
  std::vector<int> lengths_;
  std::vector<int> formats_;
  std::deque<std::string> owned_;  // numbers in network byte order; a deque never moves them
};

// What every connection of a store is opened with.
struct PgConnectionSettings {
  std::string conninfo;          // a URI or key=value string
  std::string application_name;  // replaces any in conninfo
  std::chrono::seconds connect_timeout{5};
  // How long a statement waits for a row lock (lock_timeout), and how long the
  // server keeps a transaction its client left open
  // (idle_in_transaction_session_timeout): a client that died mid-transaction
  // holds its rows no longer than that.
  std::chrono::milliseconds lock_timeout{10'000};
};

// One libpq connection. Not thread-safe: the pool hands it to one caller at a time.
class PgConnection {
 public:
  // Connects as `settings` say. Any failure → UNAVAILABLE with libpq's message.
  static StatusOr<std::unique_ptr<PgConnection>> Connect(const PgConnectionSettings& settings);
  ~PgConnection();
  PgConnection(const PgConnection&) = delete;
  PgConnection& operator=(const PgConnection&) = delete;

  // Runs one statement with `params`; `what` names it in error messages. An
  // error → a Status whose code says whether to retry (a lost connection or a
  // server shutting down → UNAVAILABLE, a serialisation failure or deadlock →
  // ABORTED, invalid text → INVALID_ARGUMENT), with PostgreSQL's message.
  StatusOr<PgResult> Execute(std::string_view sql, const PgParams& params, std::string_view what);
  // Execute for a statement outside any transaction that is safe to run twice
  // (a read, an idempotent update): a connection found dead by it (the server
  // restarted, or dropped it, since the last call) is reconnected and the
  // statement run once more.
  StatusOr<PgResult> ExecuteRetryingOnce(std::string_view sql, const PgParams& params,
                                         std::string_view what);
  // Runs one or more statements without parameters, discarding their rows.
  Status ExecuteScript(std::string_view sql, std::string_view what);

  // False once libpq has seen the connection fail; the pool replaces it.
  bool healthy() const { return PQstatus(conn_) == CONNECTION_OK; }
  // Replaces a failed connection by a new one to the same server.
  Status Reconnect();

 private:
  PgConnection(PGconn* conn, const PgConnectionSettings& settings)
      : conn_(conn), settings_(settings) {}
  // Sets the session parameters the store relies on.
  Status Configure();
  Status ErrorOf(const PGresult* result, std::string_view what) const;

  PGconn* conn_;
  PgConnectionSettings settings_;
};

// A transaction that rolls back on destruction unless Commit succeeded.
class PgTransaction {
 public:
  explicit PgTransaction(PgConnection& connection) : connection_(connection) {}
  ~PgTransaction();
  PgTransaction(const PgTransaction&) = delete;
  PgTransaction& operator=(const PgTransaction&) = delete;

  // BEGIN. A connection found broken by it (the server restarted since the last
  // call) is reconnected and BEGIN retried once: nothing had been sent yet.
  Status Begin();
  // Returns once the commit is durable (synchronous_commit is on).
  Status Commit();

 private:
  PgConnection& connection_;
  bool open_ = false;
};

// Up to `size` connections, opened on first need and reopened when broken.
class PostgresConnectionPool {
 public:
  PostgresConnectionPool(PgConnectionSettings settings, int size)
      : settings_(std::move(settings)), free_slots_(size) {}
  ~PostgresConnectionPool();

  // A connection for one operation, returned to the pool on destruction.
  class Lease {
   public:
    Lease(PostgresConnectionPool* pool, std::unique_ptr<PgConnection> connection)
        : pool_(pool), connection_(std::move(connection)) {}
    Lease(Lease&& other) noexcept = default;
    Lease& operator=(Lease&&) = delete;
    ~Lease();
    PgConnection& operator*() const { return *connection_; }
    PgConnection* operator->() const { return connection_.get(); }

   private:
    PostgresConnectionPool* pool_;
    std::unique_ptr<PgConnection> connection_;
  };

  // Waits for a free connection; connects or reconnects it if needed
  // (UNAVAILABLE if that fails).
  StatusOr<Lease> Take();

 private:
  void Return(std::unique_ptr<PgConnection> connection);

  const PgConnectionSettings settings_;
  std::mutex mutex_;
  std::condition_variable returned_;
  std::vector<std::unique_ptr<PgConnection>> idle_;  // guarded by mutex_
  int free_slots_;  // connections that may still be opened; guarded by mutex_
};

}  // namespace relmap::session
