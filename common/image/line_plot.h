// Line plots of learning curves: series over a shared x axis with "nice" ticks,
// an optional min–max envelope per series, and a legend.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/image/image.h"

namespace relmap::image {

struct Series {
  std::string name;
  Rgb colour;
  std::vector<double> x;
  std::vector<double> y;
  // Optional envelope (e.g. min and max over replications), same length as x.
  std::vector<double> low;
  std::vector<double> high;
};

struct PlotOptions {
  std::string title;
  std::string x_label;
  std::string y_label;
  int width = 900;
  int height = 560;
  std::optional<double> y_min;  // default: from the data
  std::optional<double> y_max;
};

// A distinct colour for series `index` (a fixed qualitative palette).
Rgb SeriesColour(int index);

Image RenderLinePlot(const PlotOptions& options, const std::vector<Series>& series);

}  // namespace relmap::image
