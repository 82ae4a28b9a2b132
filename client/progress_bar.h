// Progress of a long client operation on standard error: redrawn in place on a
// terminal, one line per tenth otherwise (logs and CI keep a readable record).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace relmap::client {

class ProgressBar {
 public:
  // `what` names the unit counted, e.g. "samples".
  ProgressBar(std::string what, std::uint64_t total, std::FILE* out = stderr);

  // `done` of `total` are finished.
  void Update(std::uint64_t done);
  // Ends the line with the final count and rate.
  void Finish();

  // "[#####.....]  50% 500/1000 samples  250/s  eta 2 s", `width` characters of bar.
  static std::string Line(std::uint64_t done, std::uint64_t total, const std::string& what,
                          double seconds, int width = 30);

 private:
  std::string what_;
  std::uint64_t total_;
  std::uint64_t done_ = 0;
  std::FILE* out_;
  bool terminal_;
  int last_tenth_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace relmap::client
