// nginx in front of relmap-servers, for the cluster test: deploy/nginx/relmap.conf.in
// rendered by deploy/nginx/render-conf for the given servers and a free loopback
// port, run in the foreground from a prefix directory of its own.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace relmap::testing {

class NginxProcess {
 public:
  // `directory` is created; nginx's config, pid, logs and temporary files go there.
  NginxProcess(std::string directory, std::vector<std::string> servers);
  // Stops nginx (SIGQUIT: it finishes the calls in flight).
  ~NginxProcess();
  NginxProcess(const NginxProcess&) = delete;
  NginxProcess& operator=(const NginxProcess&) = delete;

  // Renders the config and starts nginx; false (see LogTail) if it does not accept
  // connections within 10 s.
  bool Start();
  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }
  // The end of nginx's error output, for failure messages.
  std::string LogTail() const;
  // nginx's access log: one line per call with its session and upstream.
  std::string access_log() const { return directory_ + "/access.log"; }

 private:
  std::string directory_;
  std::vector<std::string> servers_;
  int port_ = 0;
  pid_t pid_ = -1;
};

// A loopback TCP port that was free a moment ago (bound, read and released).
int FreeLoopbackPort();

}  // namespace relmap::testing
