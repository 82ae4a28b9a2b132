// A real relmap-server process on a loopback port, for integration tests: started
// with --listen 127.0.0.1:0, its port read from --port-file, stopped with SIGTERM.
#pragma once

#include <grpcpp/grpcpp.h>
#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

namespace relmap::testing {

class ServerProcess {
 public:
  // Starts the server binary with `extra_arguments`; fails the test if it does
  // not bind a port within 10 s. With a `log_path`, the server's stdout and stderr
  // (its log) go to that file.
  explicit ServerProcess(std::vector<std::string> extra_arguments = {},
                         const std::string& log_path = {});
  ~ServerProcess();

  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }
  std::shared_ptr<grpc::Channel> Channel(int max_message_bytes = 64 << 20) const;
  // Sends SIGTERM and returns the exit status (as waitpid reports it).
  int Stop();
  // SIGKILL: the process dies at once, as in a crash or `kill -9`.
  void Kill();

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  std::string port_file_;
};

// GET of `path` on 127.0.0.1:`port`: the whole HTTP response, or "" if nothing
// listens there.
std::string HttpGet(int port, const std::string& path);

}  // namespace relmap::testing
