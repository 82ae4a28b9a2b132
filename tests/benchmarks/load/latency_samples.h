// Client-observed latencies of one kind of call and their percentiles. Every sample
// is kept: a run makes at most a few tens of thousands of calls.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace relmap::load {

struct LatencySummary {
  std::size_t count = 0;
  // Milliseconds; NaN when there is no sample.
  double p50 = std::numeric_limits<double>::quiet_NaN();
  double p99 = std::numeric_limits<double>::quiet_NaN();
  double mean = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

class LatencySamples {
 public:
  void Add(double milliseconds) { samples_.push_back(milliseconds); }
  std::size_t count() const { return samples_.size(); }

  // Percentiles by the nearest-rank method: p% of the samples are at or below the
  // sample of rank ⌈p/100 · n⌉ (1-based), an observed value, never an interpolation.
  LatencySummary Summarise() const {
    LatencySummary summary;
    summary.count = samples_.size();
    if (samples_.empty()) return summary;
    std::vector<double> sorted = samples_;
    std::sort(sorted.begin(), sorted.end());
    const auto nearest_rank = [&sorted](double p) {
      const auto rank =
          static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
      return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
    };
    summary.p50 = nearest_rank(50);
    summary.p99 = nearest_rank(99);
    summary.mean =
        std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(sorted.size());
    summary.max = sorted.back();
    return summary;
  }

 private:
  std::vector<double> samples_;
};

}  // namespace relmap::load
