// One row of the benchmark's table: a learner on a stream, summarised over the
// replications. The C++ learners and the Python reference fill the same row.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace relmap::learning_bench {

struct TableRow {
  std::string stream;
  std::string learner;
  int replications = 0;
  std::optional<double> balanced_accuracy_mean;  // the headline
  std::optional<double> balanced_accuracy_min;   // the worst replication
  std::optional<double> soft_accuracy;           // means over replications from here on
  std::optional<double> log_loss;
  std::optional<double> brier;
  std::optional<std::array<double, 2>> components;  // class 0, class 1
  std::optional<double> update_p50_us;              // over every Learn call of every replication
  std::optional<double> update_p99_us;
  std::optional<double> predict_us;  // per sample
};

}  // namespace relmap::learning_bench
