// Per-RPC counters and latency histograms, rendered in the Prometheus text format.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

namespace relmap::service {

class Metrics {
 public:
  // Upper bounds of the latency buckets, milliseconds (+Inf is implied).
  static constexpr std::array<double, 11> kBucketsMs = {1,   5,   10,   25,   50,  100,
                                                        250, 500, 1000, 2500, 5000};

  // Counts one call of `method` that ended with gRPC status `code`.
  void Record(std::string_view method, int code, double latency_ms);

  // The exposition text: relmap_rpc_total{method,code}, relmap_rpc_latency_ms
  // histograms per method, and the two gauges given.
  std::string PrometheusText(std::uint64_t sessions, std::uint64_t samples) const;

 private:
  struct Histogram {
    std::array<std::uint64_t, kBucketsMs.size()> buckets{};  // cumulative when rendered
    std::uint64_t count = 0;
    double sum_ms = 0.0;
  };
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> calls_;
  std::map<std::string, Histogram, std::less<>> latency_;
};

}  // namespace relmap::service
