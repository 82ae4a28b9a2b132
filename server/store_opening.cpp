// Opening the session store that --store names.
#include "store_opening.h"

#include <filesystem>
#include <string_view>
#include <system_error>

#include "session/store/postgres/postgres_session_store.h"
#include "session/store/sqlite/sqlite_session_store.h"

namespace relmap::server {
namespace {

constexpr std::string_view kSqlite = "sqlite:";

bool IsPostgresUri(std::string_view spec) {
  return spec.starts_with("postgres://") || spec.starts_with("postgresql://");
}

}  // namespace

bool IsStoreSpec(std::string_view spec) { return spec.starts_with(kSqlite) || IsPostgresUri(spec); }

StatusOr<std::unique_ptr<session::SessionStore>> OpenSessionStore(const std::string& spec,
                                                                  std::chrono::seconds lease) {
  if (spec.starts_with(kSqlite)) {
    const std::filesystem::path path(spec.substr(kSqlite.size()));
    if (path.empty()) return InvalidArgumentError("--store sqlite: needs a file path");
    std::error_code ignored;  // Open reports a directory it cannot write to
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
    auto opened = session::SqliteSessionStore::Open(path.string(), {.exclusive = true});
    if (!opened.ok()) return opened.status();
    return std::unique_ptr<session::SessionStore>(std::move(opened).value());
  }
  if (IsPostgresUri(spec)) {
    session::PostgresStoreOptions options;
    options.lease_ttl = lease;
    auto opened = session::PostgresSessionStore::Open(spec, options);
    if (!opened.ok()) return opened.status();
    return std::unique_ptr<session::SessionStore>(std::move(opened).value());
  }
  return InvalidArgumentError("--store must be sqlite:PATH or postgres://..., got '" + spec + "'");
}

std::string StoreForLogs(const std::string& spec) {
  if (!IsPostgresUri(spec)) return spec;
  // postgres://user:password@host:port/db?options: keep the scheme, host, port and
  // database; user, password and options (which may hold a password) stay out of logs.
  const std::size_t authority = spec.find("://") + 3;
  std::string rest = spec.substr(authority);
  if (const std::size_t at = rest.rfind('@', rest.find('/')); at != std::string::npos) {
    rest.erase(0, at + 1);
  }
  if (const std::size_t query = rest.find('?'); query != std::string::npos) rest.erase(query);
  return spec.substr(0, authority) + rest;
}

}  // namespace relmap::server
