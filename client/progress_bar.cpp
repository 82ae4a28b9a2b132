// Formatting is a pure function (Line) so that it can be tested without a terminal.
#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace relmap::client {

ProgressBar::ProgressBar(std::string what, std::uint64_t total, std::FILE* out)
    : what_(std::move(what)), total_(total), out_(out), terminal_(isatty(fileno(out)) == 1) {}

std::string ProgressBar::Line(std::uint64_t done, std::uint64_t total, const std::string& what,
                              double seconds, int width) {
  const double fraction =
      total == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
  const int filled = static_cast<int>(fraction * width);
  std::string line = "[";
  line.append(static_cast<std::size_t>(filled), '#');
  line.append(static_cast<std::size_t>(width - filled), '.');
  line += "] ";
  char numbers[160];
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0.0;
  std::snprintf(numbers, sizeof numbers, "%3d%% %llu/%llu %s  %.0f/s",
                static_cast<int>(fraction * 100), static_cast<unsigned long long>(done),
                static_cast<unsigned long long>(total), what.c_str(), rate);
  line += numbers;
  if (rate > 0 && done < total) {
    std::snprintf(numbers, sizeof numbers, "  eta %.0f s",
                  std::ceil(static_cast<double>(total - done) / rate));
    line += numbers;
  }
  return line;
}

void ProgressBar::Update(std::uint64_t done) {
  done_ = done;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    std::fprintf(out_, "\r%s\033[K", Line(done, total_, what_, seconds).c_str());
    std::fflush(out_);
    return;
  }
  const int tenth = total_ == 0 ? 10 : static_cast<int>(10 * done / total_);
  if (tenth == last_tenth_) return;
  last_tenth_ = tenth;
  std::fprintf(out_, "%s\n", Line(done, total_, what_, seconds).c_str());
}

void ProgressBar::Finish() {
  if (terminal_) {
    Update(done_);
    std::fputc('\n', out_);
  } else if (last_tenth_ != 10) {
    last_tenth_ = -1;
    Update(done_);
  }
}

}  // namespace relmap::client
