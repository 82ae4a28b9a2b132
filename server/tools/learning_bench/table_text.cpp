// Plain text for a terminal: a header, a rule, the rows.
#include "learning_bench/table_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace relmap::learning_bench {
namespace {

std::string Value(std::optional<double> v, int decimals) {
  return v ? fmt::format("{:.{}f}", *v, decimals) : "-";
}

}  // namespace

std::string FormatTable(const std::vector<TableRow>& rows) {
  std::size_t stream_width = 6, learner_width = 7;
  for (const TableRow& r : rows) {
    stream_width = std::max(stream_width, r.stream.size());
    learner_width = std::max(learner_width, r.learner.size());
  }
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string out =
        fmt::format("{:<{}}  {:<{}}", cells[0], stream_width, cells[1], learner_width);
    for (std::size_t i = 2; i < cells.size(); ++i) out += fmt::format("  {:>9}", cells[i]);
    return out + "\n";
  };
  std::string out = line({"stream", "learner", "bal_acc", "bal_min", "soft_acc", "log_loss",
                          "brier", "comp_0+1", "upd_p50us", "upd_p99us", "pred_us"});
  // Two names, two gaps, and nine metric cells of two spaces and nine characters.
  constexpr std::size_t kMetricCells = 9, kMetricCellWidth = 2 + 9;
  out +=
      std::string(stream_width + learner_width + 4 + kMetricCells * kMetricCellWidth, '-') + "\n";
  for (const TableRow& r : rows) {
    const std::string components =
        r.components ? fmt::format("{:.1f}+{:.1f}", (*r.components)[0], (*r.components)[1]) : "-";
    out += line({r.stream, r.learner, Value(r.balanced_accuracy_mean, 3),
                 Value(r.balanced_accuracy_min, 3), Value(r.soft_accuracy, 3), Value(r.log_loss, 3),
                 Value(r.brier, 3), components, Value(r.update_p50_us, 1),
                 Value(r.update_p99_us, 1), Value(r.predict_us, 2)});
  }
  return out;
}

std::string FormatBestLines(const std::vector<StreamBest>& best) {
  std::string out;
  for (const StreamBest& b : best) {
    if (!b.online) {
      out += fmt::format("best on {}: none (no defined balanced accuracy)\n", b.stream);
      continue;
    }
    out += fmt::format("best on {}: {} (balanced accuracy {:.3f})", b.stream, b.online->learner,
                       *b.online->balanced_accuracy_mean);
    if (b.reference) {
      out += fmt::format("; batch reference {} {:.3f}", b.reference->learner,
                         *b.reference->balanced_accuracy_mean);
    }
    out += "\n";
  }
  return out;
}

}  // namespace relmap::learning_bench
