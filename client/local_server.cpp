// posix_spawn of the server with its output redirected, then a poll of the port file
// it writes once it listens (--port-file).
#include "local_server.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <utility>

#include "common/exec_argv.h"

namespace relmap::client {
namespace {

// A new directory $TMPDIR/relmap-server-XXXXXX (or under /tmp).
StatusOr<std::string> MakeTemporaryDirectory() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern =
      std::string(base != nullptr && *base != '\0' ? base : "/tmp") + "/relmap-server-XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {
    return InternalError("cannot create a temporary directory like " + pattern);
  }
  return pattern;
}

}  // namespace

LocalServer::LocalServer(std::string directory, std::string log_path, pid_t pid)
    : directory_(std::move(directory)), log_path_(std::move(log_path)), pid_(pid) {}

StatusOr<std::unique_ptr<LocalServer>> LocalServer::Start(const std::string& binary,
                                                          const LocalServerOptions& options) {
  if (::access(binary.c_str(), X_OK) != 0) {
    return NotFoundError("no executable relmap-server at " + binary);
  }
  StatusOr<std::string> directory = MakeTemporaryDirectory();
  if (!directory.ok()) return directory.status();
  const std::string port_file = *directory + "/port";
  const std::string log_path =
      options.log_path.empty() ? *directory + "/server.log" : options.log_path;

  std::vector<std::string> arguments = {binary, "--listen", "127.0.0.1:0", "--port-file",
                                        port_file};
  if (!options.memory_only) arguments.insert(arguments.end(), {"--data-dir", *directory + "/data"});
  arguments.insert(arguments.end(), options.extra_arguments.begin(), options.extra_arguments.end());
  const std::vector<char*> argv = ExecArgv(arguments);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    std::filesystem::remove_all(*directory);
    return InternalError("cannot start " + binary + ": " + std::strerror(spawned));
  }
  std::unique_ptr<LocalServer> server(new LocalServer(*directory, log_path, pid));

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::ifstream in(port_file); in >> server->port_ && server->port_ > 0) return server;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      server->pid_ = -1;
      std::string why = binary;
      why += " exited at start-up; ";
      why += log_path;
      why += " ends:\n";
      why += server->LogTail(2000);
      return Status(StatusCode::kUnavailable, why);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return Status(StatusCode::kUnavailable, binary + " wrote no port within 15 s; " + log_path +
                                              " ends:\n" + server->LogTail(2000));
}

LocalServer::~LocalServer() {
  Stop();
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

int LocalServer::Stop() {
  if (pid_ <= 0) return -1;
  ::kill(pid_, SIGTERM);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  int status = 0;
  while (::waitpid(pid_, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() >= give_up) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  pid_ = -1;
  return status;
}

std::string LocalServer::LogTail(std::size_t bytes) const {
  std::ifstream in(log_path_, std::ios::binary);
  const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return log.size() > bytes ? log.substr(log.size() - bytes) : log;
}

}  // namespace relmap::client
