// The endpoint renders the service's counters at each scrape.
#include "metrics_endpoint.h"

#include <spdlog/spdlog.h>

#include <fstream>

namespace relmap::server {

StatusOr<std::unique_ptr<service::MetricsHttpServer>> StartMetricsEndpoint(
    const ServerOptions& options, const service::RelevanceService& service) {
  if (options.metrics_listen.empty()) return std::unique_ptr<service::MetricsHttpServer>();
  auto started = service::MetricsHttpServer::Start(options.metrics_listen,
                                                   [&service] { return service.MetricsText(); });
  if (!started.ok()) return started.status();
  spdlog::info("metrics at http://{}/metrics (port {})", options.metrics_listen,
               (*started)->port());
  if (!options.metrics_port_file.empty()) {
    std::ofstream(options.metrics_port_file) << (*started)->port() << '\n';
  }
  return started;
}

}  // namespace relmap::server
