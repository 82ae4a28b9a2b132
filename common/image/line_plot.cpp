// Layout: title on top, y label above the axis, tick labels left and below, the
// legend in one row along the bottom.
#include "common/image/line_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace relmap::image {
namespace {

constexpr Rgb kBlack = {0, 0, 0};
constexpr Rgb kGrid = {225, 225, 225};
constexpr int kLeft = 80, kRight = 20, kTop = 50, kBottom = 80;

// A tick step of 1, 2 or 5 × 10^k giving about `count` intervals over `span`.
double NiceStep(double span, int count) {
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * magnitude >= raw) return m * magnitude;
  }
  return 10.0 * magnitude;
}

Rgb Lighter(Rgb c) {
  Rgb out;
  for (int i = 0; i < 3; ++i) out[i] = static_cast<std::uint8_t>(c[i] + (255 - c[i]) * 3 / 4);
  return out;
}

struct Range {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
  }
  void Widen() {
    if (!(low < high)) {
      const double centre = std::isfinite(low) ? low : 0.0;
      low = centre - 0.5, high = centre + 0.5;
    }
  }
};

}  // namespace

Rgb SeriesColour(int index) {
  static constexpr Rgb kPalette[] = {{31, 119, 180},  {255, 127, 14},  {44, 160, 44},
                                     {214, 39, 40},   {148, 103, 189}, {140, 86, 75},
                                     {227, 119, 194}, {127, 127, 127}};
  return kPalette[index % 8];
}

Image RenderLinePlot(const PlotOptions& options, const std::vector<Series>& series) {
  Image image(options.width, options.height);
  Range xr, yr;
  for (const Series& s : series) {
    for (double v : s.x) xr.Add(v);
    for (double v : s.y) yr.Add(v);
    for (double v : s.low) yr.Add(v);
    for (double v : s.high) yr.Add(v);
  }
  if (options.y_min) yr.low = *options.y_min;
  if (options.y_max) yr.high = *options.y_max;
  xr.Widen();
  yr.Widen();

  const int x0 = kLeft, x1 = options.width - kRight, y0 = options.height - kBottom, y1 = kTop;
  const auto px = [&](double x) {
    return x0 + static_cast<int>(std::lround((x - xr.low) / (xr.high - xr.low) * (x1 - x0)));
  };
  const auto py = [&](double y) {
    return y0 - static_cast<int>(std::lround((y - yr.low) / (yr.high - yr.low) * (y0 - y1)));
  };

  // Grid and tick labels.
  const double xstep = NiceStep(xr.high - xr.low, 8);
  for (double x = std::ceil(xr.low / xstep) * xstep; x <= xr.high + 1e-9 * xstep; x += xstep) {
    image.Line(px(x), y0, px(x), y1, kGrid);
    const std::string label = fmt::format("{:g}", x);
    image.Text(px(x) - Image::TextWidth(label) / 2, y0 + 8, label, kBlack);
  }
  const double ystep = NiceStep(yr.high - yr.low, 6);
  for (double y = std::ceil(yr.low / ystep) * ystep; y <= yr.high + 1e-9 * ystep; y += ystep) {
    image.Line(x0, py(y), x1, py(y), kGrid);
    const std::string label = fmt::format("{:g}", std::abs(y) < 1e-12 ? 0.0 : y);
    image.Text(x0 - 8 - Image::TextWidth(label), py(y) - 3, label, kBlack);
  }

  // Envelopes under the lines, then the lines.
  for (const Series& s : series) {
    if (s.low.size() != s.x.size() || s.high.size() != s.x.size()) continue;
    for (std::size_t i = 1; i < s.x.size(); ++i) {
      for (int x = px(s.x[i - 1]); x <= px(s.x[i]); ++x) {
        const double t = px(s.x[i]) == px(s.x[i - 1]) ? 0.0
                                                      : static_cast<double>(x - px(s.x[i - 1])) /
                                                            (px(s.x[i]) - px(s.x[i - 1]));
        const double low = s.low[i - 1] + t * (s.low[i] - s.low[i - 1]);
        const double high = s.high[i - 1] + t * (s.high[i] - s.high[i - 1]);
        image.Line(x, py(low), x, py(high), Lighter(s.colour));
      }
    }
  }
  for (const Series& s : series) {
    for (std::size_t i = 1; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (std::isfinite(s.y[i - 1]) && std::isfinite(s.y[i])) {
        image.Line(px(s.x[i - 1]), py(s.y[i - 1]), px(s.x[i]), py(s.y[i]), s.colour, 2);
      }
    }
  }

  // Axes, titles, legend.
  image.Line(x0, y0, x1, y0, kBlack);
  image.Line(x0, y0, x0, y1, kBlack);
  image.Text((options.width - Image::TextWidth(options.title, 2)) / 2, 12, options.title, kBlack,
             2);
  image.Text((x0 + x1 - Image::TextWidth(options.x_label)) / 2, y0 + 28, options.x_label, kBlack);
  image.Text(8, y1 - 16, options.y_label, kBlack);
  // The legend runs along the bottom, outside the data.
  int legend_x = x0;
  const int legend_y = options.height - 16;
  for (const Series& s : series) {
    image.FillRect(legend_x, legend_y, legend_x + 20, legend_y + 6, s.colour);
    image.Text(legend_x + 26, legend_y, s.name, kBlack);
    legend_x += 26 + Image::TextWidth(s.name) + 24;
  }
  return image;
}

}  // namespace relmap::image
