// Aggregation over replications; nothing here knows a particular learner.
#include "learning_bench/summary.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace relmap::learning_bench {
namespace {

struct MeanMin {
  std::optional<double> mean, min;
};

MeanMin Over(const std::vector<RunResult>& runs,
             const std::function<std::optional<double>(const RunResult&)>& score) {
  double sum = 0.0, low = std::numeric_limits<double>::infinity();
  int count = 0;
  for (const RunResult& run : runs) {
    if (const auto v = score(run)) sum += *v, low = std::min(low, *v), ++count;
  }
  if (count == 0) return {};
  return {sum / count, low};
}

}  // namespace

TableRow Summarise(const std::string& stream, const std::string& learner,
                   const std::vector<RunResult>& runs, const tools::LatencyRecorder& updates) {
  TableRow row;
  row.stream = stream;
  row.learner = learner;
  row.replications = static_cast<int>(runs.size());
  const MeanMin balanced = Over(runs, [](const RunResult& r) { return r.balanced_accuracy; });
  row.balanced_accuracy_mean = balanced.mean;
  row.balanced_accuracy_min = balanced.min;
  row.soft_accuracy = Over(runs, [](const RunResult& r) { return r.soft_accuracy; }).mean;
  row.log_loss = Over(runs, [](const RunResult& r) { return r.log_loss; }).mean;
  row.brier = Over(runs, [](const RunResult& r) { return r.brier; }).mean;
  row.predict_us = Over(runs, [](const RunResult& r) { return r.predict_us; }).mean;
  const auto components = [&](int label) {
    return Over(runs,
                [label](const RunResult& r) -> std::optional<double> {
                  if (!r.components) return std::nullopt;
                  return (*r.components)[static_cast<std::size_t>(label)];
                })
        .mean;
  };
  if (const auto c0 = components(0), c1 = components(1); c0 && c1) {
    row.components = std::array<double, 2>{*c0, *c1};
  }
  const tools::LatencyRecorder::Summary latency = updates.Summarise();
  if (latency.count > 0) row.update_p50_us = latency.p50, row.update_p99_us = latency.p99;
  return row;
}

CurveSummary SummariseCurves(const std::string& stream, const std::string& learner,
                             const std::vector<RunResult>& runs) {
  CurveSummary curve{stream, learner, {}, {}, {}, {}};
  if (runs.empty()) return curve;
  std::size_t points = runs.front().curve.size();
  for (const RunResult& run : runs) points = std::min(points, run.curve.size());
  for (std::size_t i = 0; i < points; ++i) {
    std::vector<double> values;
    for (const RunResult& run : runs) {
      if (const auto v = run.curve[i].balanced_accuracy) values.push_back(*v);
    }
    if (values.size() != runs.size()) continue;
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    double sum = 0.0;
    for (const double v : values) sum += v;
    curve.samples.push_back(runs.front().curve[i].samples);
    curve.mean.push_back(sum / static_cast<double>(values.size()));
    curve.min.push_back(*low);
    curve.max.push_back(*high);
  }
  return curve;
}

std::vector<StreamBest> BestPerStream(const std::vector<TableRow>& rows,
                                      const std::vector<std::string>& streams,
                                      const std::vector<std::string>& references) {
  const auto better = [](const TableRow& a, const std::optional<TableRow>& b) {
    if (!a.balanced_accuracy_mean) return false;
    if (!b) return true;
    const double infinity = std::numeric_limits<double>::infinity();
    return *a.balanced_accuracy_mean > *b->balanced_accuracy_mean ||
           (*a.balanced_accuracy_mean == *b->balanced_accuracy_mean &&
            a.log_loss.value_or(infinity) < b->log_loss.value_or(infinity));
  };
  std::vector<StreamBest> out;
  for (const std::string& stream : streams) {
    StreamBest best{stream, std::nullopt, std::nullopt};
    for (const TableRow& r : rows) {
      if (r.stream != stream) continue;
      const bool reference =
          std::find(references.begin(), references.end(), r.learner) != references.end();
      std::optional<TableRow>& slot = reference ? best.reference : best.online;
      if (better(r, slot)) slot = r;
    }
    if (best.reference && best.online && !better(*best.reference, best.online)) {
      best.reference.reset();
    }
    out.push_back(std::move(best));
  }
  return out;
}

}  // namespace relmap::learning_bench
