// What the views of parameter_space.png share (optimize_figures.h, ParameterSpaceFigure): a set's
// value of a searched parameter, a parameter's axis and title, and the quarters of a value among
// the evaluated sets with their colours. And the view of two searched parameters, whose scatter
// grid is a file of its own (scatter_grid_figure.cc). Used by parameter_space_figures.cc and
// scatter_grid_figure.cc only.
#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/optimize_result.h"
#include "slamtune/report/figures/optimize_figures.h"
#include "slamtune/report/figures/plot.h"

namespace slamtune::report {

// The set's value of the searched parameter `name`; none when it has none or it is not finite.
std::optional<double> SearchedValueOf(const optim::EvaluationRecord& r, const std::string& name);
// A parameter's search range with a 4 % margin either side (a range of one value gets a width).
AxisLimits SearchRangeAxis(const optim::Dimension& d);
// "r = loop_search_maximum_distance", or the name alone when it has no short name.
std::string DimensionTitle(const optim::Dimension& d);

// Quarter boundaries of `values` (sorted ascending): the values at 25, 50 and 75 % of them.
std::array<double, 3> QuarterCuts(const std::vector<double>& values);
// The quarter (0, best, to 3) of `v` among the values cut at `cut`.
int QuarterOf(double v, const std::array<double, 3>& cut);
// Best quarter green, then sky blue, orange, and the worst reddish purple.
cv::Scalar QuarterColour(int q);
// The quarter's legend text: "<= 1.5 m", "1.5 - 2 m", "> 3 m".
std::string QuarterName(int q, const std::array<double, 3>& cut, const std::string& unit);

// parameter_space.png for two searched parameters (ParameterSpaceView::kScatterGrid).
cv::Mat ScatterGridFigure(const optim::OptimizeResult& result, const FigureOptions& options);

}  // namespace slamtune::report
