// Latency samples and their order statistics, for the tools' reports.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace relmap::tools {

class LatencyRecorder {
 public:
  struct Summary {
    double p50 = 0, p99 = 0, max = 0;  // microseconds
    int count = 0;
  };

  // Runs `work` and records how long it took.
  template <typename Work>
  auto Time(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    if constexpr (std::is_void_v<decltype(work())>) {
      work();
      Record(start);
    } else {
      auto result = work();
      Record(start);
      return result;
    }
  }

  // Nearest-rank percentiles of the recorded durations.
  Summary Summarise() const {
    Summary s;
    s.count = static_cast<int>(micros_.size());
    if (micros_.empty()) return s;
    std::vector<double> sorted = micros_;
    std::sort(sorted.begin(), sorted.end());
    const auto rank = [&](double q) {
      const auto index =
          static_cast<std::size_t>(std::lround(q * static_cast<double>(sorted.size() - 1)));
      return sorted[index];
    };
    s.p50 = rank(0.50);
    s.p99 = rank(0.99);
    s.max = sorted.back();
    return s;
  }

 private:
  void Record(std::chrono::steady_clock::time_point start) {
    micros_.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
  }
  std::vector<double> micros_;
};

}  // namespace relmap::tools
