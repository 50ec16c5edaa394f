// The base configuration's sequential matches along the log (optimize_figures.h).
#include <fmt/format.h>

#include "slamtune/report/figures/optimize_figures.h"
#include "slamtune/slam/front_end_evidence.h"

namespace slamtune::report {

cv::Mat FrontEndFigure(const optim::BaseFrontEnd& front_end, const FigureOptions& options) {
  options.Validate();
  Series all = MakeSeries(fmt::format("sequential matches ({})", front_end.steps.size()), {}, {});
  all.colour = PaletteColour(0);
  all.marker = Marker::kCircle;
  all.marker_size = 3;
  Series edge = MakeSeries("at the search's edge", {}, {});
  edge.colour = PaletteColour(4);
  edge.marker = Marker::kDiamond;
  edge.marker_size = 9;
  Series broke = MakeSeries("break", {}, {});
  broke.colour = PaletteColour(1);
  broke.marker = Marker::kStar;
  broke.marker_size = 18;
  const double median = front_end.evidence.median_response;
  for (std::size_t i = 0; i < front_end.steps.size(); ++i) {
    const slam::SequentialMatchStep& s = front_end.steps[i];
    all.x.push_back(s.time);
    all.y.push_back(s.response);
    if (s.at_window_edge || s.at_heading_edge) {
      edge.x.push_back(s.time);
      edge.y.push_back(s.response);
    }
    if (slam::IsBreak(front_end.steps, i, median, {})) {
      broke.x.push_back(s.time);
      broke.y.push_back(s.response);
    }
  }
  PlotOptions o = options.panel.Plot();
  o.width = 3 * options.panel.width;
  o.x_label = "seconds into the log";
  o.y_label = "sequential match response";
  o.y_limits = AxisLimits{0.0, 1.0};
  o.title = "The base configuration's front end along the log";
  return RenderPlot({all, edge, broke}, o).image;
}

}  // namespace slamtune::report
