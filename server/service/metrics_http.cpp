// POSIX sockets; a scrape every few seconds needs nothing more.
#include "service/metrics_http.h"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>

namespace relmap::service {

StatusOr<std::unique_ptr<MetricsHttpServer>> MetricsHttpServer::Start(
    const std::string& address, std::function<std::string()> render) {
  const auto colon = address.rfind(':');
  if (colon == std::string::npos) return InvalidArgumentError("metrics address needs host:port");
  sockaddr_in in{};
  in.sin_family = AF_INET;
  in.sin_port = htons(static_cast<std::uint16_t>(std::stoi(address.substr(colon + 1))));
  if (::inet_pton(AF_INET, address.substr(0, colon).c_str(), &in.sin_addr) != 1) {
    return InvalidArgumentError("metrics address '" + address + "' is not IPv4 host:port");
  }
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&in), sizeof in) != 0 ||
      ::listen(fd, 16) != 0) {
    const std::string reason = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    return Status(StatusCode::kUnavailable, "cannot listen on " + address + ": " + reason);
  }
  socklen_t length = sizeof in;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&in), &length);
  return std::unique_ptr<MetricsHttpServer>(
      new MetricsHttpServer(fd, ntohs(in.sin_port), std::move(render)));
}

MetricsHttpServer::MetricsHttpServer(int socket, int port, std::function<std::string()> render)
    : socket_(socket), port_(port), render_(std::move(render)), thread_([this] { Serve(); }) {}

MetricsHttpServer::~MetricsHttpServer() {
  stopping_ = true;
  ::shutdown(socket_, SHUT_RDWR);  // wakes accept()
  thread_.join();
  ::close(socket_);
}

void MetricsHttpServer::Serve() {
  while (!stopping_) {
    const int client = ::accept4(socket_, nullptr, nullptr, SOCK_CLOEXEC);
    if (client < 0) continue;
    char request[1024];
    const ssize_t got = ::recv(client, request, sizeof request - 1, 0);
    const std::string_view head(request, got > 0 ? static_cast<std::size_t>(got) : 0);
    std::string body = "not found\n";
    std::string status = "404 Not Found";
    if (head.starts_with("GET /metrics ") || head.starts_with("GET /metrics?")) {
      body = render_();
      status = "200 OK";
    }
    const std::string response = fmt::format(
        "HTTP/1.0 {}\r\nContent-Type: text/plain; version=0.0.4\r\nContent-Length: {}\r\n"
        "Connection: close\r\n\r\n{}",
        status, body.size(), body);
    for (std::size_t sent = 0; sent < response.size();) {
      const ssize_t n =
          ::send(client, response.data() + sent, response.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;
      sent += static_cast<std::size_t>(n);
    }
    ::close(client);
  }
}

}  // namespace relmap::service
