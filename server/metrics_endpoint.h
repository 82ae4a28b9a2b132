// relmap-server's Prometheus endpoint, when --metrics-listen asks for one.
#pragma once

#include <memory>

#include "common/status.h"
#include "server_options.h"
#include "service/metrics_http.h"
#include "service/relevance_service.h"

namespace relmap::server {

// Serving `service`'s metrics, its port written to --metrics-port-file if given;
// null without --metrics-listen; the listener's error when it cannot listen.
StatusOr<std::unique_ptr<service::MetricsHttpServer>> StartMetricsEndpoint(
    const ServerOptions& options, const service::RelevanceService& service);

}  // namespace relmap::server
