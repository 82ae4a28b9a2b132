// Prometheus text exposition format 0.0.4.
#include "service/metrics.h"

#include <fmt/format.h>

namespace relmap::service {
namespace {

// The canonical name of a gRPC status code, as Prometheus label value.
std::string_view CodeName(int code) {
  static constexpr std::string_view kNames[] = {"OK",
                                                "CANCELLED",
                                                "UNKNOWN",
                                                "INVALID_ARGUMENT",
                                                "DEADLINE_EXCEEDED",
                                                "NOT_FOUND",
                                                "ALREADY_EXISTS",
                                                "PERMISSION_DENIED",
                                                "RESOURCE_EXHAUSTED",
                                                "FAILED_PRECONDITION",
                                                "ABORTED",
                                                "OUT_OF_RANGE",
                                                "UNIMPLEMENTED",
                                                "INTERNAL",
                                                "UNAVAILABLE",
                                                "DATA_LOSS",
                                                "UNAUTHENTICATED"};
  return code >= 0 && code < 17 ? kNames[code] : "UNKNOWN";
}

}  // namespace

void Metrics::Record(std::string_view method, int code, double latency_ms) {
  std::lock_guard lock(mutex_);
  ++calls_[{std::string(method), code}];
  auto it = latency_.find(method);
  if (it == latency_.end()) it = latency_.emplace(std::string(method), Histogram{}).first;
  Histogram& h = it->second;
  for (std::size_t b = 0; b < kBucketsMs.size(); ++b) {
    if (latency_ms <= kBucketsMs[b]) {
      ++h.buckets[b];
      break;
    }
  }
  ++h.count;
  h.sum_ms += latency_ms;
}

std::string Metrics::PrometheusText(std::uint64_t sessions, std::uint64_t samples) const {
  std::lock_guard lock(mutex_);
  std::string out;
  out += "# HELP relmap_rpc_total RPCs served, by method and gRPC status.\n";
  out += "# TYPE relmap_rpc_total counter\n";
  for (const auto& [key, count] : calls_) {
    out += fmt::format("relmap_rpc_total{{method=\"{}\",code=\"{}\"}} {}\n", key.first,
                       CodeName(key.second), count);
  }
  out += "# HELP relmap_rpc_latency_ms Time inside the server per RPC, milliseconds.\n";
  out += "# TYPE relmap_rpc_latency_ms histogram\n";
  for (const auto& [method, h] : latency_) {
    std::uint64_t cumulative = 0;
    for (std::size_t b = 0; b < kBucketsMs.size(); ++b) {
      cumulative += h.buckets[b];
      out += fmt::format("relmap_rpc_latency_ms_bucket{{method=\"{}\",le=\"{}\"}} {}\n", method,
                         kBucketsMs[b], cumulative);
    }
    out += fmt::format("relmap_rpc_latency_ms_bucket{{method=\"{}\",le=\"+Inf\"}} {}\n", method,
                       h.count);
    out += fmt::format("relmap_rpc_latency_ms_sum{{method=\"{}\"}} {}\n", method, h.sum_ms);
    out += fmt::format("relmap_rpc_latency_ms_count{{method=\"{}\"}} {}\n", method, h.count);
  }
  out += "# HELP relmap_sessions Sessions in this server's memory.\n# TYPE relmap_sessions gauge\n";
  out += fmt::format("relmap_sessions {}\n", sessions);
  out +=
      "# HELP relmap_samples Labelled samples of the sessions in memory.\n# TYPE relmap_samples "
      "gauge\n";
  out += fmt::format("relmap_samples {}\n", samples);
  return out;
}

}  // namespace relmap::service
