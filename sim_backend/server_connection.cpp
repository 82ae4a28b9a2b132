// Starting the server, then the client with the default deadline and retries.
#include "server_connection.h"

#include <cstdlib>
#include <utility>

#include "server_binary.h"

namespace relmap::sim {

StatusOr<ServerConnection> ConnectOrStartServer(const std::string& server,
                                                const std::string& server_binary,
                                                const client::LocalServerOptions& options,
                                                const char* command, std::FILE* notes) {
  ServerConnection connection;
  connection.address = server;
  if (connection.address.empty()) {
    StatusOr<std::string> binary = client::FindServerBinary(server_binary);
    if (!binary.ok()) return binary.status();
    StatusOr<std::unique_ptr<client::LocalServer>> started =
        client::LocalServer::Start(*binary, options);
    if (!started.ok()) return started.status();
    connection.launched = std::move(*started);
    connection.address = connection.launched->address();
    std::fprintf(notes, "%s: started %s on %s (log in %s)\n", command, binary->c_str(),
                 connection.address.c_str(), connection.launched->log_path().c_str());
  }
  client::ClientOptions client_options;
  client_options.address = connection.address;
  connection.client = std::make_unique<client::RelevanceClient>(client_options);
  if (const char* key = std::getenv("RELMAP_ADMIN_KEY"); key != nullptr && *key != '\0') {
    connection.client->set_admin_key(key);
  }
  return connection;
}

}  // namespace relmap::sim
