// One image::Series per curve, its envelope from spread.h.
#include "plots.h"

#include <optional>
#include <string>

#include "common/image/line_plot.h"
#include "spread.h"

namespace relmap::sim {
namespace {

using Extract = std::function<std::optional<double>(const IterationRecord&)>;

image::Series SeriesOf(const std::vector<ReplicationResult>& replications, const std::string& name,
                       int colour, const Extract& of) {
  Envelope envelope = EnvelopeOver(replications, of);
  image::Series series;
  series.name = name;
  series.colour = image::SeriesColour(colour);
  series.x = std::move(envelope.x);
  series.y = std::move(envelope.mean);
  series.low = std::move(envelope.low);
  series.high = std::move(envelope.high);
  return series;
}

Status Plot(const std::string& path, const std::string& title, const std::string& y_label,
            std::optional<double> y_max, const std::vector<image::Series>& series) {
  image::PlotOptions options;
  options.title = title;
  options.x_label = "iteration";
  options.y_label = y_label;
  options.y_min = 0.0;
  options.y_max = y_max;
  return image::WritePng(image::RenderLinePlot(options, series), path);
}

// A score of one metric, as an Extract.
Extract ScoreOf(metrics::Scores IterationRecord::*metric,
                std::optional<double> metrics::Scores::*score) {
  return [metric, score](const IterationRecord& i) { return i.*metric.*score; };
}

}  // namespace

Status WriteCurvePlots(const std::vector<ReplicationResult>& replications,
                       const std::string& directory) {
  using metrics::Scores;
  const std::string suffix = " (mean, min-max over " + std::to_string(replications.size()) +
                             (replications.size() == 1 ? " replication)" : " replications)");
  for (const auto& [name, score] :
       {std::pair{"accuracy", &Scores::accuracy}, std::pair{"precision", &Scores::precision},
        std::pair{"recall", &Scores::recall}}) {
    Status written =
        Plot(directory + "/" + name + ".png", std::string(name) + suffix, name, 1.0,
             {SeriesOf(replications, "thresholded-soft", 0,
                       ScoreOf(&IterationRecord::thresholded, score)),
              SeriesOf(replications, "soft", 1, ScoreOf(&IterationRecord::soft, score))});
    if (!written.ok()) return written;
  }
  const auto count = [](auto field) -> Extract {
    return [field](const IterationRecord& i) {
      return std::optional<double>(static_cast<double>(i.model.*field));
    };
  };
  Status written =
      Plot(directory + "/samples.png", "samples per class" + suffix, "samples", std::nullopt,
           {SeriesOf(replications, "moveable", 0, count(&ModelCounts::moveable_samples)),
            SeriesOf(replications, "non-moveable", 1, count(&ModelCounts::non_moveable_samples))});
  if (!written.ok()) return written;
  return Plot(
      directory + "/components.png", "components per class" + suffix, "components", std::nullopt,
      {SeriesOf(replications, "moveable", 0, count(&ModelCounts::moveable_components)),
       SeriesOf(replications, "non-moveable", 1, count(&ModelCounts::non_moveable_components))});
}

}  // namespace relmap::sim
