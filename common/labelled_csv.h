// Labelled samples as CSV: one row `label,f1,...,fp` per sample, an optional
// header line. What `relmap-cmm`, `relmap-bench-learning` and `relmap stream` read, and
// `relmap-dataset` and `relmap-sim dataset` write.
#pragma once

#include <Eigen/Core>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "common/status.h"

namespace relmap::datasets {

struct LabelledSamples {
  Eigen::MatrixXd features;  // one sample per row
  std::vector<int> labels;   // 0 or 1, one per row
};

// Reads a whole file. Ragged rows, non-numeric or non-finite values, labels
// other than 0/1 and files without a data row → INVALID_ARGUMENT naming the
// file and line; an unreadable file → NOT_FOUND.
StatusOr<LabelledSamples> ReadLabelledCsv(const std::string& path);
// The same from a stream; `name` is used in messages.
StatusOr<LabelledSamples> ParseLabelledCsv(std::istream& in, const std::string& name);

// Writes a header `label,f1,...,fp` and one row per sample, values printed so
// that they read back exactly.
void WriteLabelledCsv(const LabelledSamples& samples, std::ostream& out);

// The same row by row, for samples that are not held in one matrix: the header for
// `dimension` features, then one line per sample, each value in the shortest decimal
// that reads back to the same double (std::to_chars: no locale, the same bytes on
// every machine).
void WriteLabelledCsvHeader(std::size_t dimension, std::ostream& out);
void WriteLabelledCsvRow(int label, std::span<const double> features, std::ostream& out);

}  // namespace relmap::datasets
