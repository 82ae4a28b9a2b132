// A relmap-server child process that relmap-load starts for one run: loopback,
// a port of the kernel's choosing, and a temporary directory for its data, port
// file and log, removed when the object goes.
#pragma once

#include <sys/types.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/status.h"

namespace relmap::load {

class LaunchedServer {
 public:
  // Starts `binary` with --listen 127.0.0.1:0, --port-file, --data-dir (unless
  // `memory_only`) and `extra_arguments`; its standard output and error go to
  // server.log in the temporary directory. UNAVAILABLE, with the log's tail, when
  // it has not written its port within 15 s or has exited.
  static StatusOr<std::unique_ptr<LaunchedServer>> Start(
      const std::string& binary, bool memory_only, const std::vector<std::string>& extra_arguments);
  // Stops the server (if still running) and removes the temporary directory.
  ~LaunchedServer();
  LaunchedServer(const LaunchedServer&) = delete;
  LaunchedServer& operator=(const LaunchedServer&) = delete;

  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }
  pid_t pid() const { return pid_; }

  // SIGTERM (the server drains its calls) and waits, SIGKILL after 15 s; the exit
  // status as waitpid gives it, or -1 when it was already stopped.
  int Stop();

 private:
  LaunchedServer(std::string directory, pid_t pid) : directory_(std::move(directory)), pid_(pid) {}
  // The last `bytes` of server.log, for error messages.
  std::string LogTail(std::size_t bytes) const;

  std::string directory_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace relmap::load
