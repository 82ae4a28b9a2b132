// The two files: the labelled CSV through common/labelled_csv.h, the frames beside it.
#include "dataset_csv.h"

#include <fstream>

#include "common/labelled_csv.h"

namespace relmap::sim {
Status FileWritten(std::ofstream& file, const std::string& path) {
  file.flush();
  if (!file) return InternalError("cannot write " + path);
  return OkStatus();
}

Status WriteDataset(const std::vector<DatasetRow>& rows, const std::string& csv_path,
                    const std::string& frames_path) {
  std::ofstream csv(csv_path, std::ios::binary | std::ios::trunc);
  std::ofstream frames(frames_path, std::ios::binary | std::ios::trunc);
  datasets::WriteLabelledCsvHeader(rows.empty() ? 0 : rows.front().features.size(), csv);
  frames << "frame,body,object\n";
  for (const DatasetRow& row : rows) {
    datasets::WriteLabelledCsvRow(row.moveable ? 1 : 0, row.features, csv);
    frames << row.frame << ',' << row.body << ',' << row.object << '\n';
  }
  if (Status status = FileWritten(csv, csv_path); !status.ok()) return status;
  return FileWritten(frames, frames_path);
}

}  // namespace relmap::sim
