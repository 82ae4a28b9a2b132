// The PostgreSQL store kind of the contract tests and the one throw-away server
// its test program shares: started once by a global test environment, a schema
// of its own for each test.
#pragma once

#include <optional>
#include <string>

#include "session/store/postgres/postgres_session_store.h"
#include "session/store_backend.h"
#include "support/postgres_instance.h"

namespace relmap::session::testing {

// The server of this test program; nullptr (and every test failing) if it did
// not start.
relmap::testing::PostgresInstance* SharedPostgres();

// A place of its own for a test on the shared server: a new, empty schema of
// one database (CREATE DATABASE costs 0.2 s with fsync on; a schema, ms).
struct PostgresScratch {
  std::string database;
  std::string schema;
  // The database's URI with the schema as search_path: what a store opens.
  std::string uri;
};
// The scratch space, or nullopt (with a test failure) if it could not be made.
std::optional<PostgresScratch> NewPostgresScratch();

// The PostgreSQL kind: a new schema per test on the shared server.
StoreKind PostgresKind();

}  // namespace relmap::session::testing
