// What the store contract tests run against: a store kind (SQLite, PostgreSQL)
// that gives each test a database of its own, opened as often as the test
// likes. Each Open is another store instance on the same data: a restarted
// server, or a second server.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "common/status.h"
#include "session/store/session_store.h"

namespace relmap::session::testing {

// One statement per dialect, for tampering with stored data behind a store's back.
struct DialectSql {
  const char* sqlite;
  const char* postgres;
};

class StoreBackend {
 public:
  virtual ~StoreBackend() = default;
  // A new store instance on this test's database.
  virtual StatusOr<std::unique_ptr<SessionStore>> Open() = 0;
  // Runs the statement of this backend's dialect on the database, as a damaged
  // disk or a future server version would leave it. False (with a test failure)
  // if it did not run.
  virtual bool Tamper(const DialectSql& sql) = 0;
};

struct StoreKind {
  std::string name;  // the instantiation's name: Sqlite, Postgres
  // The backend for the test named `test_id` (unique in the test program).
  std::function<std::unique_ptr<StoreBackend>(const std::string& test_id)> make;
};

// gtest prints a kind by its name.
inline void PrintTo(const StoreKind& kind, std::ostream* out) { *out << kind.name; }

// The SQLite kind: a file under ::testing::TempDir(), removed afterwards.
StoreKind SqliteKind();

}  // namespace relmap::session::testing
