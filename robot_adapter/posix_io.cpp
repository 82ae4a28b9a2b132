// Pipes and sockets with deadlines.
#include "posix_io.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>

namespace relmap::robot {
namespace {

std::string Errno(const std::string& what) { return what + ": " + std::strerror(errno); }

// "host:port" or "[v6]:port" into its parts; false when malformed.
bool SplitAddress(const std::string& address, std::string* host, std::string* port) {
  const std::size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon + 1 == address.size()) return false;
  *host = address.substr(0, colon);
  *port = address.substr(colon + 1);
  if (host->size() >= 2 && host->front() == '[' && host->back() == ']') {
    *host = host->substr(1, host->size() - 2);
  }
  return port->find_first_not_of("0123456789") == std::string::npos;
}

using AddressList = std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)>;

StatusOr<AddressList> Resolve(const std::string& address, bool passive) {
  std::string host;
  std::string port;
  if (!SplitAddress(address, &host, &port)) {
    return InvalidArgumentError("\"" + address + "\" is not host:port");
  }
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = passive ? AI_PASSIVE : 0;
  addrinfo* found = nullptr;
  const int error =
      ::getaddrinfo(host.empty() ? nullptr : host.c_str(), port.c_str(), &hints, &found);
  if (error != 0) {
    return Status(StatusCode::kUnavailable,
                  "cannot resolve " + address + ": " + ::gai_strerror(error));
  }
  return AddressList(found, &::freeaddrinfo);
}

// One connect attempt to `candidate`, non-blocking, within `deadline`.
StatusOr<UniqueFd> ConnectOne(const addrinfo& candidate, Clock::time_point deadline) {
  UniqueFd socket(::socket(candidate.ai_family,
                           candidate.ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK,
                           candidate.ai_protocol));
  if (!socket.valid()) return Status(StatusCode::kUnavailable, Errno("socket"));
  if (::connect(socket.get(), candidate.ai_addr, candidate.ai_addrlen) != 0) {
    if (errno != EINPROGRESS) return Status(StatusCode::kUnavailable, Errno("connect"));
    for (;;) {
      pollfd writable{socket.get(), POLLOUT, 0};
      const int ready = ::poll(&writable, 1, MillisecondsLeft(deadline));
      if (ready < 0 && errno == EINTR) continue;
      if (ready == 0) return Status(StatusCode::kDeadlineExceeded, "connect: timed out");
      if (ready < 0) return Status(StatusCode::kUnavailable, Errno("poll"));
      break;
    }
    int error = 0;
    socklen_t length = sizeof error;
    ::getsockopt(socket.get(), SOL_SOCKET, SO_ERROR, &error, &length);
    if (error != 0) {
      return Status(StatusCode::kUnavailable, std::string("connect: ") + std::strerror(error));
    }
  }
  // Blocking again: reads and writes wait with poll() and their own deadlines.
  ::fcntl(socket.get(), F_SETFL, ::fcntl(socket.get(), F_GETFL) & ~O_NONBLOCK);
  const int one = 1;
  ::setsockopt(socket.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  return socket;
}

}  // namespace

UniqueFd& UniqueFd::operator=(UniqueFd&& other) noexcept {
  if (this != &other) reset(other.release());
  return *this;
}

int UniqueFd::release() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

void UniqueFd::reset(int fd) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
}

int MillisecondsLeft(Clock::time_point deadline) {
  if (deadline == Clock::time_point::max()) return -1;
  // Rounded up: a wait of this long ends at the deadline, not just before it.
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() > 0 ? static_cast<int>(left.count()) : 0;
}

bool WriteAll(int fd, std::string_view data) {
  std::size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  return true;
}

StatusOr<Wait> WaitReadable(int fd, Clock::time_point deadline, const std::atomic<bool>* stop) {
  constexpr int kTickMs = 100;
  for (;;) {
    if (stop != nullptr && stop->load()) return Wait::kStopped;
    const int left = MillisecondsLeft(deadline);
    if (left == 0) return Wait::kTimedOut;
    pollfd readable{fd, POLLIN, 0};
    const int ready = ::poll(&readable, 1, left < 0 || left > kTickMs ? kTickMs : left);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return InternalError(Errno("poll"));
    if (ready > 0) return Wait::kReady;
  }
}

StatusOr<UniqueFd> ConnectTcp(const std::string& address, std::chrono::milliseconds timeout) {
  StatusOr<AddressList> candidates = Resolve(address, false);
  if (!candidates.ok()) return candidates.status();
  const Clock::time_point deadline = Clock::now() + timeout;
  Status last = Status(StatusCode::kUnavailable, "no address");
  for (const addrinfo* candidate = candidates->get(); candidate != nullptr;
       candidate = candidate->ai_next) {
    StatusOr<UniqueFd> connected = ConnectOne(*candidate, deadline);
    if (connected.ok()) return connected;
    last = connected.status();
  }
  return Status(last.code(), "cannot connect to " + address + " (" + last.message() + ")");
}

StatusOr<UniqueFd> ListenTcp(const std::string& address) {
  StatusOr<AddressList> candidates = Resolve(address, true);
  if (!candidates.ok()) return candidates.status();
  std::string reason = "no address";
  for (const addrinfo* candidate = candidates->get(); candidate != nullptr;
       candidate = candidate->ai_next) {
    UniqueFd socket(::socket(candidate->ai_family, candidate->ai_socktype | SOCK_CLOEXEC,
                             candidate->ai_protocol));
    if (!socket.valid()) {
      reason = Errno("socket");
      continue;
    }
    const int one = 1;
    ::setsockopt(socket.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(socket.get(), candidate->ai_addr, candidate->ai_addrlen) != 0 ||
        ::listen(socket.get(), 4) != 0) {
      reason = Errno("bind");
      continue;
    }
    return socket;
  }
  return Status(StatusCode::kUnavailable, "cannot listen on " + address + " (" + reason + ")");
}

int LocalPort(int fd) {
  sockaddr_storage local{};
  socklen_t length = sizeof local;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&local), &length) != 0) return -1;
  if (local.ss_family == AF_INET) {
    return ntohs(reinterpret_cast<const sockaddr_in*>(&local)->sin_port);
  }
  if (local.ss_family == AF_INET6) {
    return ntohs(reinterpret_cast<const sockaddr_in6*>(&local)->sin6_port);
  }
  return -1;
}

}  // namespace relmap::robot
