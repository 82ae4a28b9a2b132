// A minimal HTTP endpoint for Prometheus: GET /metrics answers the text a
// callback renders; anything else is 404. One thread, one request per connection.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "common/status.h"

namespace relmap::service {

class MetricsHttpServer {
 public:
  // Listens on `address` ("host:port", an IPv4 host; port 0 picks one).
  static StatusOr<std::unique_ptr<MetricsHttpServer>> Start(const std::string& address,
                                                            std::function<std::string()> render);
  ~MetricsHttpServer();

  int port() const { return port_; }

 private:
  MetricsHttpServer(int socket, int port, std::function<std::string()> render);
  void Serve();

  int socket_;
  int port_;
  std::function<std::string()> render_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace relmap::service
