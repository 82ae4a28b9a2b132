// The exec driver: fork, exec, a pipe each way, a deadline, SIGKILL on timeout.
#include "exec_driver.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <thread>

#include "common/exec_argv.h"
#include "posix_io.h"

namespace relmap::robot {
namespace {

// The child's side: its own process group, the pipes as stdin and stdout, exec.
// It writes its error in pieces: it must not allocate (see common/exec_argv.h).
[[noreturn]] void ExecChild(char* const* argv, int stdin_fd, int stdout_fd) {
  ::setpgid(0, 0);
  ::dup2(stdin_fd, STDIN_FILENO);
  ::dup2(stdout_fd, STDOUT_FILENO);
  ::execvp(argv[0], argv);
  const char* reason = std::strerror(errno);
  for (const char* piece :
       {"relmap-robot: cannot run ", static_cast<const char*>(argv[0]), ": ", reason, "\n"})
    (void)!::write(STDERR_FILENO, piece, std::strlen(piece));
  ::_exit(127);
}

}  // namespace

ExecDriver::ExecDriver(std::vector<std::string> command, std::chrono::milliseconds timeout)
    : command_(std::move(command)), timeout_(timeout) {
  std::signal(SIGPIPE, SIG_IGN);
}

StatusOr<PushOutcome> ExecDriver::Push(const DriverRequest& target) {
  if (command_.empty()) return InvalidArgumentError("the exec driver has no command");
  const std::string request = DriverRequestJson(target) + "\n";

  int to_child[2];
  int from_child[2];
  if (::pipe2(to_child, O_CLOEXEC) != 0)
    return InternalError("pipe: " + std::string(strerror(errno)));
  if (::pipe2(from_child, O_CLOEXEC) != 0) {
    ::close(to_child[0]);
    ::close(to_child[1]);
    return InternalError("pipe: " + std::string(strerror(errno)));
  }
  const std::vector<char*> argv = ExecArgv(command_);
  const pid_t pid = ::fork();
  if (pid == 0) ExecChild(argv.data(), to_child[0], from_child[1]);
  ::close(to_child[0]);
  ::close(from_child[1]);
  if (pid < 0) {
    ::close(to_child[1]);
    ::close(from_child[0]);
    return InternalError("fork: " + std::string(strerror(errno)));
  }
  ::setpgid(pid, pid);  // also here, so that a kill right away reaches the group
  const Clock::time_point deadline = Clock::now() + timeout_;
  // A command that answers without reading the target is fine: EPIPE is ignored.
  (void)WriteAll(to_child[1], request);
  ::close(to_child[1]);

  // Its whole stdout, until it closes it or the deadline.
  std::string output;
  bool timed_out = false;
  for (;;) {
    pollfd readable{from_child[0], POLLIN, 0};
    const int left = MillisecondsLeft(deadline);
    const int ready = ::poll(&readable, 1, left);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {
      timed_out = true;
      break;
    }
    char buffer[4096];
    const ssize_t n = ::read(from_child[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    output.append(buffer, static_cast<std::size_t>(n));
    if (output.size() > (1u << 20)) break;  // no driver answers a megabyte
  }
  ::close(from_child[0]);

  // Its exit, within what is left of the deadline.
  int wait_status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &wait_status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR)
      return InternalError("waitpid: " + std::string(strerror(errno)));
    if (timed_out || MillisecondsLeft(deadline) == 0) {
      timed_out = true;
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &wait_status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (timed_out) {
    return Status(StatusCode::kDeadlineExceeded,
                  "driver " + command_[0] + " did not answer within " +
                      std::to_string(timeout_.count()) + " ms; killed");
  }
  if (WIFSIGNALED(wait_status)) {
    return Status(StatusCode::kUnknown, "driver " + command_[0] + " was killed by signal " +
                                            std::to_string(WTERMSIG(wait_status)));
  }
  if (WEXITSTATUS(wait_status) != 0) {
    return Status(StatusCode::kUnknown, "driver " + command_[0] + " exited with status " +
                                            std::to_string(WEXITSTATUS(wait_status)));
  }
  return ParseDriverResult(output);
}

}  // namespace relmap::robot
