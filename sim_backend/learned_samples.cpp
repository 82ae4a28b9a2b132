// The pairing walks the two sequences side by side; the files go through
// common/labelled_csv.h like dataset_csv.cpp's.
#include "learned_samples.h"

#include <fstream>

#include "common/labelled_csv.h"
#include "dataset_csv.h"

namespace relmap::sim {
StatusOr<std::vector<LearnedSample>> PairLearnedSamples(
    const std::vector<IterationRecord>& iterations, const v1::SessionState& state) {
  std::vector<LearnedSample> samples;
  int next = 0;
  for (const IterationRecord& record : iterations) {
    if (!record.label || !record.truth || !record.target) continue;
    if (next >= state.samples_size()) {
      return FailedPreconditionError(
          "the session holds " + std::to_string(state.samples_size()) +
          " samples, fewer than the iterations that learned one (iteration " +
          std::to_string(record.iteration) + " has none)");
    }
    const v1::LabelledFeature& stored = state.samples(next++);
    const bool label = stored.label() == v1::LABEL_MOVEABLE;
    if (label != *record.label) {
      return FailedPreconditionError("sample " + std::to_string(next) + " is labelled " +
                                     (label ? "moveable" : "not moveable") + ", iteration " +
                                     std::to_string(record.iteration) + " learned the other label");
    }
    const auto& values = stored.feature().values();
    samples.push_back(
        {record.iteration, *record.target, label, *record.truth, {values.begin(), values.end()}});
  }
  if (next != state.samples_size()) {
    return FailedPreconditionError(
        "the session holds " + std::to_string(state.samples_size()) + " samples, " +
        std::to_string(next) +
        " iterations learned one: it learned more than the pushed targets (--labels object?)");
  }
  return samples;
}

Status WriteLearnedSamples(const std::vector<LearnedSample>& samples, const std::string& csv_path,
                           const std::string& truth_csv_path, const std::string& iterations_path) {
  const std::size_t dimension = samples.empty() ? 0 : samples.front().features.size();
  std::ofstream csv(csv_path, std::ios::binary | std::ios::trunc);
  datasets::WriteLabelledCsvHeader(dimension, csv);
  for (const LearnedSample& s : samples) {
    datasets::WriteLabelledCsvRow(s.label ? 1 : 0, s.features, csv);
  }
  if (Status status = FileWritten(csv, csv_path); !status.ok()) return status;
  if (!truth_csv_path.empty()) {
    std::ofstream truth(truth_csv_path, std::ios::binary | std::ios::trunc);
    datasets::WriteLabelledCsvHeader(dimension, truth);
    for (const LearnedSample& s : samples) {
      datasets::WriteLabelledCsvRow(s.truth ? 1 : 0, s.features, truth);
    }
    if (Status status = FileWritten(truth, truth_csv_path); !status.ok()) return status;
  }
  std::ofstream rows(iterations_path, std::ios::binary | std::ios::trunc);
  rows << "iteration,target,label,truth\n";
  for (const LearnedSample& s : samples) {
    rows << s.iteration << ',' << s.target << ',' << (s.label ? 1 : 0) << ',' << (s.truth ? 1 : 0)
         << '\n';
  }
  return FileWritten(rows, iterations_path);
}

}  // namespace relmap::sim
