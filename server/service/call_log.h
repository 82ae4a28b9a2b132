// One spdlog line and one metrics record per RPC: method, session, status, latency.
#pragma once

#include <grpcpp/support/status.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <string>
#include <string_view>

#include "service/metrics.h"

namespace relmap::service {

// Runs `body` (returning grpc::Status) and logs how it went. `session_id` is read
// after the body ran, so CreateSession can log the id it made.
template <typename Body>
grpc::Status Logged(Metrics& metrics, std::string_view method, const std::string& session_id,
                    Body&& body) {
  const auto start = std::chrono::steady_clock::now();
  grpc::Status status = body();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  metrics.Record(method, static_cast<int>(status.error_code()), ms);
  if (status.ok()) {
    spdlog::info("rpc={} session={} status=OK latency_ms={:.2f}", method,
                 session_id.empty() ? "-" : session_id, ms);
  } else {
    spdlog::warn("rpc={} session={} status={} latency_ms={:.2f} message=\"{}\"", method,
                 session_id.empty() ? "-" : session_id, static_cast<int>(status.error_code()), ms,
                 status.error_message());
  }
  return status;
}

}  // namespace relmap::service
