// How the search progressed, generation by generation (optimize_figures.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/report/figures/optimize_figures.h"

namespace slamtune::report {

cv::Mat HistoryFigure(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  const optim::OptimizationHistory& h = result.history;
  if (h.generations.empty()) return {};
  const double last = h.generations.back().generation;
  const AxisLimits x_limits{0.0, std::max(1.0, last)};
  std::vector<cv::Mat> panels;
  for (std::size_t k = 0; k < result.objectives.size(); ++k) {
    Series best = MakeSeries("", {}, {}, SeriesStyle::kLineAndMarkers);
    best.colour = PaletteColour(k);
    best.marker = Marker::kCircle;
    best.marker_size = 6;
    for (const optim::GenerationSummary& g : h.generations) {
      if (k >= g.best.size()) continue;
      best.x.push_back(g.generation);
      best.y.push_back(g.best[k]);  // NaN (no successful run) is skipped
    }
    PlotOptions o = options.panel.Plot();
    o.x_limits = x_limits;
    o.x_label = "generation";
    o.x_whole_numbers = true;
    o.y_label = ObjectiveAt(result, k).title;
    o.title = fmt::format("best {} of each generation (lower is better)", ObjectiveAt(result, k).short_name);
    o.legend = false;
    panels.push_back(RenderPlot({best}, o).image);
  }
  Series hv = MakeSeries("", {}, {}, SeriesStyle::kLineAndMarkers);
  hv.colour = PaletteColour(0);
  hv.marker = Marker::kSquare;
  hv.marker_size = 6;
  for (const optim::GenerationSummary& g : h.generations) {
    hv.x.push_back(g.generation);
    hv.y.push_back(g.hypervolume);
  }
  PlotOptions o = options.panel.Plot();
  o.x_limits = x_limits;
  o.y_limits = AxisLimits{0.0, std::pow(optim::kHypervolumeReference, static_cast<double>(result.objectives.size()))};
  o.x_label = "generation";
  o.x_whole_numbers = true;
  o.y_label = "hypervolume (normalised objectives)";
  o.title = "hypervolume of the front (higher is better)";
  o.legend = false;
  panels.push_back(RenderPlot({hv}, o).image);
  GridOptions g;
  g.columns = 2;
  g.title = fmt::format("The search generation by generation ({} to {})", h.generations.front().generation,
                        h.generations.back().generation);
  return ComposeGrid(panels, g);
}

}  // namespace slamtune::report
