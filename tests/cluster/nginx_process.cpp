// Rendering, starting and stopping nginx for the cluster test.
#include "cluster/nginx_process.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "common/exec_argv.h"

namespace relmap::testing {
namespace {

bool Accepts(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool connected = ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);
  return connected;
}

// Runs `arguments` with standard output to `output` and standard error to `errors`;
// returns the child's pid, or -1.
pid_t Spawn(std::vector<std::string> arguments, const std::string& output,
            const std::string& errors) {
  const std::vector<char*> argv = ExecArgv(arguments);
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  const int out = ::open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = ::open(errors.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (out < 0 || err < 0) ::_exit(126);
  ::dup2(out, STDOUT_FILENO);
  ::dup2(err, STDERR_FILENO);
  ::execvp(argv[0], argv.data());
  ::_exit(127);
}

int WaitFor(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace

int FreeLoopbackPort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(fd);
    return 0;
  }
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(fd);
  return ntohs(address.sin_port);
}

NginxProcess::NginxProcess(std::string directory, std::vector<std::string> servers)
    : directory_(std::move(directory)), servers_(std::move(servers)) {}

NginxProcess::~NginxProcess() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGQUIT);
  WaitFor(pid_);
}

bool NginxProcess::Start() {
  std::filesystem::create_directories(directory_);
  // nginx's workers run as an unprivileged user when the test runs as root: they
  // must be able to enter the prefix.
  ::chmod(directory_.c_str(), 0755);
  port_ = FreeLoopbackPort();
  const std::string config = directory_ + "/nginx.conf";
  std::vector<std::string> render = {RELMAP_NGINX_RENDER, "--listen", address(), "--access-log",
                                     access_log()};
  for (const std::string& server : servers_) render.insert(render.end(), {"--server", server});
  if (WaitFor(Spawn(render, config, directory_ + "/error.log")) != 0) return false;
  pid_ = Spawn({"nginx", "-p", directory_, "-c", config, "-g", "daemon off;"},
               directory_ + "/nginx.out", directory_ + "/error.log");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    if (Accepts(port_)) return true;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {  // exited: a bad config
      pid_ = -1;
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

std::string NginxProcess::LogTail() const {
  std::ifstream in(directory_ + "/error.log");
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  return text.size() > 2000 ? text.substr(text.size() - 2000) : text;
}

}  // namespace relmap::testing
