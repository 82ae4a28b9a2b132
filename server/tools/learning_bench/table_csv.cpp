// Writing and reading the shared schema; the column list is the one place that
// names it.
#include "learning_bench/table_csv.h"

#include <fmt/format.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace relmap::learning_bench {
namespace {

enum Column {
  kStream,
  kLearner,
  kReplications,
  kBalancedMean,
  kBalancedMin,
  kSoft,
  kLogLoss,
  kBrier,
  kComponents,
  kUpdateP50,
  kUpdateP99,
  kPredict,
  kColumnCount
};
constexpr std::array<const char*, kColumnCount> kColumns = {"stream",
                                                            "learner",
                                                            "replications",
                                                            "balanced_accuracy_mean",
                                                            "balanced_accuracy_min",
                                                            "soft_accuracy",
                                                            "log_loss",
                                                            "brier",
                                                            "components",
                                                            "update_p50_us",
                                                            "update_p99_us",
                                                            "predict_us"};

std::string Cell(std::optional<double> value) { return value ? fmt::format("{:.6g}", *value) : ""; }

std::vector<std::string> Split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, separator);) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

// An empty cell is undefined; anything else must be a whole number.
StatusOr<std::optional<double>> ParseCell(const std::string& text, const std::string& where) {
  if (text.empty()) return std::optional<double>();
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') {
    return InvalidArgumentError(where + ": '" + text + "' is not a number");
  }
  return std::optional<double>(value);
}

}  // namespace

std::string TableCsv(const std::vector<TableRow>& rows) {
  std::string out;
  for (const char* column : kColumns) out += fmt::format("{}{}", out.empty() ? "" : ",", column);
  out += '\n';
  for (const TableRow& r : rows) {
    const std::string components =
        r.components ? fmt::format("{:.6g}+{:.6g}", (*r.components)[0], (*r.components)[1]) : "";
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", r.stream, r.learner, r.replications,
                       Cell(r.balanced_accuracy_mean), Cell(r.balanced_accuracy_min),
                       Cell(r.soft_accuracy), Cell(r.log_loss), Cell(r.brier), components,
                       Cell(r.update_p50_us), Cell(r.update_p99_us), Cell(r.predict_us));
  }
  return out;
}

StatusOr<std::vector<TableRow>> ReadTableCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) return NotFoundError("cannot open " + path);
  std::string line;
  if (!std::getline(in, line)) return InvalidArgumentError(path + ": empty file");
  const std::vector<std::string> header = Split(line, ',');
  std::array<std::size_t, kColumns.size()> at{};
  for (std::size_t c = 0; c < kColumns.size(); ++c) {
    std::size_t i = 0;
    while (i < header.size() && header[i] != kColumns[c]) ++i;
    if (i == header.size()) return InvalidArgumentError(path + ": no column " + kColumns[c]);
    at[c] = i;
  }
  std::vector<TableRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(number);
    const std::vector<std::string> f = Split(line, ',');
    if (f.size() != header.size()) return InvalidArgumentError(where + ": ragged row");
    std::array<std::optional<double>, kColumns.size()> v{};
    for (std::size_t c = kReplications; c < kColumns.size(); ++c) {
      if (c == kComponents) continue;  // "c0+c1", below
      auto cell = ParseCell(f[at[c]], where);
      if (!cell.ok()) return cell.status();
      v[c] = *cell;
    }
    TableRow r{f[at[kStream]],   f[at[kLearner]], static_cast<int>(v[kReplications].value_or(0)),
               v[kBalancedMean], v[kBalancedMin], v[kSoft],
               v[kLogLoss],      v[kBrier],       std::nullopt,
               v[kUpdateP50],    v[kUpdateP99],   v[kPredict]};
    if (const auto parts = Split(f[at[kComponents]], '+'); parts.size() == 2) {
      auto c0 = ParseCell(parts[0], where), c1 = ParseCell(parts[1], where);
      if (!c0.ok()) return c0.status();
      if (!c1.ok()) return c1.status();
      if (*c0 && *c1) r.components = std::array<double, 2>{**c0, **c1};
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace relmap::learning_bench
