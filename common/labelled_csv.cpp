// CSV reading with a precise error for every malformed row.
#include "common/labelled_csv.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <string_view>
#include <vector>

namespace relmap::datasets {
namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> SplitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(Trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

bool ParseDouble(std::string_view field, double& value) {
  const char* end = field.data() + field.size();
  const auto [ptr, error] = std::from_chars(field.data(), end, value);
  return error == std::errc() && ptr == end;
}

// A header names its columns: its first field is a word, where a data row has
// its label. ("1,nan,..." is a data row, and its NaN an error.)
bool LooksLikeHeader(const std::vector<std::string_view>& fields) {
  double ignored = 0.0;
  const std::string_view first = fields.front();
  return !first.empty() && std::isalpha(static_cast<unsigned char>(first.front())) &&
         !ParseDouble(first, ignored);
}

}  // namespace

StatusOr<LabelledSamples> ReadLabelledCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) return NotFoundError(path + ": cannot open the file");
  return ParseLabelledCsv(in, path);
}

StatusOr<LabelledSamples> ParseLabelledCsv(std::istream& in, const std::string& name) {
  std::vector<double> values;
  std::vector<int> labels;
  int dimension = -1;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string_view text = Trim(line);
    if (text.empty()) continue;
    const auto fields = SplitFields(text);
    const auto where = [&](const std::string& what) {
      return InvalidArgumentError(fmt::format("{}:{}: {}", name, number, what));
    };
    if (labels.empty() && LooksLikeHeader(fields)) continue;
    if (fields.size() < 2) return where("a row needs a label and at least one feature");
    const int p = static_cast<int>(fields.size()) - 1;
    if (dimension >= 0 && p != dimension) {
      return where(fmt::format("row has {} features, earlier rows have {}", p, dimension));
    }
    dimension = p;
    if (fields[0] != "0" && fields[0] != "1") {
      return where(fmt::format("label '{}' is not 0 or 1", fields[0]));
    }
    labels.push_back(fields[0] == "1" ? 1 : 0);
    for (int k = 1; k <= p; ++k) {
      double v = 0.0;
      if (!ParseDouble(fields[k], v))
        return where(fmt::format("field {} '{}' is not a number", k + 1, fields[k]));
      if (!std::isfinite(v))
        return where(fmt::format("field {} '{}' is not finite", k + 1, fields[k]));
      values.push_back(v);
    }
  }
  if (labels.empty()) return InvalidArgumentError(name + ": no data row");

  LabelledSamples samples;
  const auto n = static_cast<Eigen::Index>(labels.size());
  samples.features =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          values.data(), n, dimension);
  samples.labels = std::move(labels);
  return samples;
}

void WriteLabelledCsvHeader(std::size_t dimension, std::ostream& out) {
  std::string line = "label";
  for (std::size_t k = 1; k <= dimension; ++k) line += ",f" + std::to_string(k);
  line += '\n';
  out << line;
}

void WriteLabelledCsvRow(int label, std::span<const double> features, std::ostream& out) {
  std::string line = std::to_string(label);
  char text[32];
  for (const double value : features) {
    const auto [end, error] = std::to_chars(text, text + sizeof text, value);
    line += ',';
    line.append(text, end);
  }
  line += '\n';
  out << line;
}

void WriteLabelledCsv(const LabelledSamples& samples, std::ostream& out) {
  WriteLabelledCsvHeader(static_cast<std::size_t>(samples.features.cols()), out);
  std::vector<double> row(static_cast<std::size_t>(samples.features.cols()));
  for (Eigen::Index i = 0; i < samples.features.rows(); ++i) {
    for (Eigen::Index k = 0; k < samples.features.cols(); ++k) {
      row[static_cast<std::size_t>(k)] = samples.features(i, k);
    }
    WriteLabelledCsvRow(samples.labels[static_cast<std::size_t>(i)], row, out);
  }
}

}  // namespace relmap::datasets
