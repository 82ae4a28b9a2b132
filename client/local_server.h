// A relmap-server child process for programs that run their own (relmap-sim without
// --server, relmap-load): loopback, a port of the kernel's choosing, a temporary
// directory for its data and port file (removed when the object goes), its output
// in a log file. Stopped with SIGTERM, so it drains its calls.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

#include "common/status.h"

namespace relmap::client {

struct LocalServerOptions {
  // No --data-dir: sessions in memory only.
  bool memory_only = false;
  // More flags for the server (e.g. --max-threads 4).
  std::vector<std::string> extra_arguments;
  // Where its standard output and error go; empty: server.log in its directory.
  std::string log_path;
};

class LocalServer {
 public:
  // Starts `binary`. NOT_FOUND when it is not executable; UNAVAILABLE, with the log's
  // tail, when it exits or has not written its port within 15 s.
  static StatusOr<std::unique_ptr<LocalServer>> Start(const std::string& binary,
                                                      const LocalServerOptions& options = {});
  // Stops the server (if still running) and removes its directory.
  ~LocalServer();
  LocalServer(const LocalServer&) = delete;
  LocalServer& operator=(const LocalServer&) = delete;

  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }
  pid_t pid() const { return pid_; }
  const std::string& log_path() const { return log_path_; }

  // SIGTERM and a wait, SIGKILL if it has not ended within 15 s (it drains calls for
  // at most 10 s: past that it is hung); the wait status, or -1 if already stopped.
  int Stop();

 private:
  LocalServer(std::string directory, std::string log_path, pid_t pid);
  // The last `bytes` of the log, for error messages.
  std::string LogTail(std::size_t bytes) const;

  std::string directory_;
  std::string log_path_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace relmap::client
