// The SQLite session store's schema and the migrations that bring a database
// file of any earlier version up to the current one.
#pragma once

#include <sqlite3.h>

#include "common/status.h"

namespace relmap::session {

// The schema version this build writes.
int CurrentSchemaVersion();

// Creates the schema in an empty database or applies the missing migrations, in
// one transaction. A database newer than this build → FAILED_PRECONDITION.
Status MigrateSchema(sqlite3* db);

}  // namespace relmap::session
