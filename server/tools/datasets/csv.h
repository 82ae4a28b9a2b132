// Labelled samples as CSV: one row `label,f1,...,fp` per sample, an optional
// header line. What `relmap-cmm` reads and `relmap-dataset` writes.
#pragma once

#include <iosfwd>
#include <string>

#include "common/status.h"
#include "datasets/synthetic_problems.h"

namespace relmap::datasets {

// Reads a whole file. Ragged rows, non-numeric or non-finite values, labels
// other than 0/1 and files without a data row → INVALID_ARGUMENT naming the
// file and line; an unreadable file → NOT_FOUND.
StatusOr<LabelledSamples> ReadLabelledCsv(const std::string& path);
// The same from a stream; `name` is used in messages.
StatusOr<LabelledSamples> ParseLabelledCsv(std::istream& in, const std::string& name);

// Writes a header `label,f1,...,fp` and one row per sample, values printed so
// that they read back exactly.
void WriteLabelledCsv(const LabelledSamples& samples, std::ostream& out);

}  // namespace relmap::datasets
