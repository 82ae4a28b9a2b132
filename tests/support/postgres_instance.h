// A throw-away PostgreSQL server for tests: a fresh cluster in a temporary
// directory, listening on a free loopback port, stopped and removed on
// destruction.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::testing {

struct PostgresInstanceOptions {
  // fsync on: a commit is on disk before it is acknowledged, as in production;
  // the store's durability tests rely on it.
  bool fsync = true;
  // PostgreSQL's server programs (Debian's postgresql package).
  std::string bin_directory = "/usr/lib/postgresql/15/bin";
};

// initdb into a temporary directory, then `postgres` on 127.0.0.1 at a free
// port with its Unix socket in that directory, superuser "postgres" trusted.
// initdb refuses to run as root: under euid 0 the server programs run as the
// `postgres` system user (runuser), which then owns the directory.
class PostgresInstance {
 public:
  // Starts the server and waits until it accepts connections. UNAVAILABLE with
  // the server's log when it does not start.
  static StatusOr<std::unique_ptr<PostgresInstance>> Start(
      const PostgresInstanceOptions& options = {});
  // Stops the server (fast shutdown) and removes the directory.
  ~PostgresInstance();
  PostgresInstance(const PostgresInstance&) = delete;
  PostgresInstance& operator=(const PostgresInstance&) = delete;

  int port() const { return port_; }
  // postgresql://postgres@127.0.0.1:<port>/<database>
  std::string Uri(std::string_view database) const;

  // Creates database `name` (an SQL identifier, quoted as such).
  Status CreateDatabase(std::string_view name);
  // Runs `sql` in `database` as the superuser, rows discarded: tampering with
  // stored data behind a store's back, terminating backends.
  Status Execute(std::string_view database, std::string_view sql);
  // The first column of the first row `sql` returns (its last statement's, if
  // several), as text; NOT_FOUND if it returns no row, "" for NULL.
  StatusOr<std::string> Query(std::string_view database, std::string_view sql);

 private:
  PostgresInstance(std::string directory, int port, PostgresInstanceOptions options)
      : directory_(std::move(directory)), port_(port), options_(std::move(options)) {}

  std::string directory_;  // holds data/, the socket and server.log
  int port_;
  PostgresInstanceOptions options_;
};

}  // namespace relmap::testing
