// The PostgreSQL session store's schema and the migrations that bring a
// database of any earlier version up to the current one.
#pragma once

#include "common/status.h"
#include "session/store/postgres/postgres_connection.h"

namespace relmap::session {

// The schema version this build writes.
int CurrentPostgresSchemaVersion();

// Creates the schema in an empty database or applies the missing migrations, in
// one transaction under an advisory lock, so that servers starting together
// migrate one after the other. A database newer than this build →
// FAILED_PRECONDITION.
Status MigratePostgresSchema(PgConnection& connection);

}  // namespace relmap::session
