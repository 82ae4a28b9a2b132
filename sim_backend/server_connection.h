// The relmap-server a relmap-sim command talks to: the one --server names, or one it
// starts itself (client/local_server.h) for as long as the connection lives.
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "common/status.h"
#include "local_server.h"
#include "relevance_client.h"

namespace relmap::sim {

struct ServerConnection {
  std::unique_ptr<client::LocalServer> launched;  // null when --server was given
  std::string address;
  // Sends RELMAP_ADMIN_KEY from the environment when it is set.
  std::unique_ptr<client::RelevanceClient> client;
};

// `server` (host:port) when not empty; else starts FindServerBinary(`server_binary`)
// with `options` and says so on `notes` as "<command>: started ...". Errors are
// FindServerBinary's (NOT_FOUND) and LocalServer::Start's.
StatusOr<ServerConnection> ConnectOrStartServer(const std::string& server,
                                                const std::string& server_binary,
                                                const client::LocalServerOptions& options,
                                                const char* command, std::FILE* notes);

}  // namespace relmap::sim
