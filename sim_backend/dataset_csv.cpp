// The two files, through std::to_chars: shortest round-trip decimals without a locale,
// so that the same rows give the same bytes on every machine.
#include "dataset_csv.h"

#include <charconv>
#include <fstream>

namespace relmap::sim {
namespace {

void AppendNumber(double value, std::string* line) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  line->append(text, end);
}

Status Written(std::ofstream& file, const std::string& path) {
  file.flush();
  if (!file) return InternalError("cannot write " + path);
  return OkStatus();
}

}  // namespace

Status WriteDataset(const std::vector<DatasetRow>& rows, const std::string& csv_path,
                    const std::string& frames_path) {
  std::ofstream csv(csv_path, std::ios::binary | std::ios::trunc);
  std::ofstream frames(frames_path, std::ios::binary | std::ios::trunc);
  std::string line = "label";
  const std::size_t dimension = rows.empty() ? 0 : rows.front().features.size();
  for (std::size_t k = 1; k <= dimension; ++k) line += ",f" + std::to_string(k);
  csv << line << '\n';
  frames << "frame\n";
  for (const DatasetRow& row : rows) {
    line.assign(1, row.moveable ? '1' : '0');
    for (const double value : row.features) {
      line += ',';
      AppendNumber(value, &line);
    }
    csv << line << '\n';
    frames << row.frame << '\n';
  }
  if (Status status = Written(csv, csv_path); !status.ok()) return status;
  return Written(frames, frames_path);
}

}  // namespace relmap::sim
