// The y axis ends at 1 on every stream so that the PNGs compare at a glance;
// its lower end follows the data, since label noise can push a learner below
// chance.
#include "learning_bench/curve_plot.h"

#include <fmt/format.h>

#include "common/image/line_plot.h"

namespace relmap::learning_bench {

Status WriteCurvePng(const std::string& stream, const std::vector<CurveSummary>& curves,
                     const std::string& path) {
  std::vector<image::Series> series;
  for (const CurveSummary& c : curves) {
    if (c.stream != stream) continue;
    const int index = static_cast<int>(series.size());
    series.push_back({c.learner, image::SeriesColour(index), c.samples, c.mean, c.min, c.max});
  }
  image::PlotOptions options;
  options.title = stream + ": held-out balanced accuracy";
  options.x_label = "training samples";
  options.y_label = "balanced accuracy";
  options.y_max = 1.0;
  return image::WritePng(image::RenderLinePlot(options, series), path);
}

std::string CurvesCsv(const std::vector<CurveSummary>& curves) {
  std::string out = "stream,learner,samples,mean,min,max\n";
  for (const CurveSummary& c : curves) {
    for (std::size_t i = 0; i < c.samples.size(); ++i) {
      out += fmt::format("{},{},{},{:.6g},{:.6g},{:.6g}\n", c.stream, c.learner, c.samples[i],
                         c.mean[i], c.min[i], c.max[i]);
    }
  }
  return out;
}

}  // namespace relmap::learning_bench
