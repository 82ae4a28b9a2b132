// The relmap-servers a chaos run kills, each on a fixed loopback port so that its
// clients (or nginx) find it again after a restart: one on SQLite, one on a
// throw-away PostgreSQL, or two on PostgreSQL behind nginx as deploy/nginx has them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "chaos/chaos_options.h"
#include "cluster/nginx_process.h"
#include "common/status.h"
#include "local_server.h"
#include "support/postgres_instance.h"

namespace relmap::chaos {

class ServerFleet {
 public:
  // Starts the store, the servers and (for the cluster) nginx, their files in
  // `directory`. FAILED_PRECONDITION when PostgreSQL's or nginx's programs are not
  // installed; another error when something does not start.
  static StatusOr<std::unique_ptr<ServerFleet>> Start(StoreKind kind,
                                                      const std::string& server_binary,
                                                      const std::string& directory);
  ~ServerFleet();
  ServerFleet(const ServerFleet&) = delete;
  ServerFleet& operator=(const ServerFleet&) = delete;

  // What the sessions dial: the server, or nginx in front of the servers.
  std::string address() const;
  int servers() const { return static_cast<int>(servers_.size()); }

  // The server whose log last mentions a call on `session_id` (which serves it, as
  // far as its log tells), or -1 when none does.
  int LastServing(const std::string& session_id) const;
  // kill -9 of server `i`; it is dead and reaped when this returns.
  void Kill(int i);
  // Starts server `i` on its port and the store; the seconds from its start to its
  // first SERVING answer of grpc.health.v1.
  StatusOr<double> Restart(int i);

 private:
  struct Server {
    int port = 0;
    int starts = 0;
    std::unique_ptr<client::LocalServer> process;
  };

  ServerFleet(StoreKind kind, std::string server_binary, std::string directory)
      : kind_(kind), server_binary_(std::move(server_binary)), directory_(std::move(directory)) {}
  // The flags that put a server on the store.
  std::vector<std::string> StoreArguments() const;

  StoreKind kind_;
  std::string server_binary_;
  std::string directory_;
  std::unique_ptr<testing::PostgresInstance> postgres_;
  std::vector<Server> servers_;
  std::unique_ptr<testing::NginxProcess> nginx_;
};

}  // namespace relmap::chaos
