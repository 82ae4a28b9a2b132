// relmap-plot: draws columns of CSV files (e.g. the learning curves that
// `relmap-cmm --curve-csv` writes) as one PNG line plot.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/command_line.h"
#include "common/image/line_plot.h"

namespace {

constexpr std::string_view kUsage =
    "usage: relmap-plot --out plot.png --x COLUMN --y COLUMN [--title T] [--x-label X]\n"
    "                   [--y-label Y] [--y-min A] [--y-max B] NAME=FILE.csv [NAME=FILE.csv ...]\n"
    "  Each FILE has a header line naming its columns, then numeric rows.\n";

[[noreturn]] void Fail(const std::string& message) {
  relmap::tools::ExitWithError("relmap-plot", message);
}

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  return fields;
}

// Reads columns `x` and `y` of a CSV file with a header.
relmap::image::Series ReadSeries(const std::string& name, const std::string& path,
                                 const std::string& x, const std::string& y) {
  std::ifstream in(path);
  if (!in) Fail("cannot open " + path);
  std::string line;
  if (!std::getline(in, line)) Fail(path + ": empty file");
  const std::vector<std::string> header = Split(line);
  const auto column = [&](const std::string& wanted) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == wanted) return i;
    }
    Fail(path + ": no column '" + wanted + "'");
  };
  const std::size_t xi = column(x), yi = column(y);
  relmap::image::Series series;
  series.name = name;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = Split(line);
    if (fields.size() != header.size()) Fail(path + ":" + std::to_string(number) + ": ragged row");
    char* end = nullptr;
    const double xv = std::strtod(fields[xi].c_str(), &end);
    const double yv = std::strtod(fields[yi].c_str(), &end);
    series.x.push_back(xv);
    series.y.push_back(yv);
  }
  return series;
}

}  // namespace

int main(int argc, char** argv) {
  relmap::image::PlotOptions options;
  std::string out, x, y;
  std::vector<relmap::image::Series> series;
  std::vector<std::pair<std::string, std::string>> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) Fail(std::string(arg) + " needs a value");
      return argv[++i];
    };
    if (arg == "--out")
      out = value();
    else if (arg == "--x")
      x = value();
    else if (arg == "--y")
      y = value();
    else if (arg == "--title")
      options.title = value();
    else if (arg == "--x-label")
      options.x_label = value();
    else if (arg == "--y-label")
      options.y_label = value();
    else if (arg == "--y-min")
      options.y_min = relmap::tools::ParseNumberOrExit("relmap-plot", arg, value().c_str());
    else if (arg == "--y-max")
      options.y_max = relmap::tools::ParseNumberOrExit("relmap-plot", arg, value().c_str());
    else if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage.data(), stdout);
      return 0;
    } else if (const auto eq = arg.find('='); eq != std::string_view::npos && arg[0] != '-') {
      inputs.emplace_back(std::string(arg.substr(0, eq)), std::string(arg.substr(eq + 1)));
    } else {
      Fail("unknown argument '" + std::string(arg) + "'\n" + std::string(kUsage));
    }
  }
  if (out.empty() || x.empty() || y.empty() || inputs.empty()) Fail(std::string(kUsage));
  for (const auto& [name, path] : inputs) {
    series.push_back(ReadSeries(name, path, x, y));
    series.back().colour = relmap::image::SeriesColour(static_cast<int>(series.size()) - 1);
  }
  if (options.x_label.empty()) options.x_label = x;
  if (options.y_label.empty()) options.y_label = y;
  const relmap::Status status =
      relmap::image::WritePng(relmap::image::RenderLinePlot(options, series), out);
  if (!status.ok()) Fail(status.message());
  return 0;
}
