// A dataset's rows on disk: the labelled CSV that relmap-cmm and relmap-bench-learning
// read (common/labelled_csv.h), and beside it each row's frame.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "common/status.h"
#include "dataset_frame.h"

namespace relmap::sim {

// `csv_path`: a header "label,f1,...,fp", then per row its label (0/1) and features,
// each printed in the shortest form that reads back to the same double. `frames_path`:
// a header "frame,body,object", then per row, in the same order, its frame, the body it
// shows (DatasetRow::body; -1 for none) and the object the server sees it on
// (DatasetRow::object). Both stay out
// of the CSV because every column after the label is a feature to its readers.
// INTERNAL naming the file when one cannot be written.
// OK once `file` (written to `path`) is flushed without error, else INTERNAL naming it.
Status FileWritten(std::ofstream& file, const std::string& path);

Status WriteDataset(const std::vector<DatasetRow>& rows, const std::string& csv_path,
                    const std::string& frames_path);

}  // namespace relmap::sim
