// Where the search went in parameter space (optimize_figures.h): which view parameter_space.png
// shows, the slices of one objective against each parameter, parallel coordinates of three or more
// parameters, and what these views share with the scatter grid of two (scatter_grid_figure.cc).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/report/figures/optimize_figures.h"
#include "slamtune/report/figures/parameter_space_parts.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {

std::optional<double> SearchedValueOf(const optim::EvaluationRecord& r, const std::string& name) {
  const auto it = r.params.find(name);
  if (it == r.params.end() || !std::isfinite(it->second)) return std::nullopt;
  return it->second;
}

AxisLimits SearchRangeAxis(const optim::Dimension& d) {
  const double range = d.upper > d.lower ? d.upper - d.lower : std::max(std::abs(d.lower), 1.0);
  return {d.lower - 0.04 * range, (d.upper > d.lower ? d.upper : d.lower + range) + 0.04 * range};
}

std::string DimensionTitle(const optim::Dimension& d) {
  const std::string s = ShortParamName(d.name);
  return s == d.name ? d.name : s + " = " + d.name;
}

namespace {

// Candidates' markers at (their value of x, their value of y).
void AddCandidates(std::vector<Series>& series, const optim::OptimizeResult& result,
                   const std::function<std::optional<std::pair<double, double>>(const optim::Candidate&)>& at) {
  for (const CandidateGroup& g : MergedCandidates(result)) {
    for (const auto* c : g.members) {
      if (const auto p = at(*c)) series.push_back(CandidateSeries(*c, p->first, p->second));
    }
  }
}

}  // namespace

ParameterSpaceView ParameterSpaceViewOf(const optim::OptimizeResult& result) {
  const std::size_t n = result.space.dimensions.size();
  if (n == 0 || result.evaluations.empty() || result.objectives.size() == 0) return ParameterSpaceView::kNone;
  if (n == 1) return ParameterSpaceView::kSlices;
  return n == 2 ? ParameterSpaceView::kScatterGrid : ParameterSpaceView::kParallelCoordinates;
}

// Quarter boundaries of `values` (sorted ascending): the values at 25, 50 and 75 % of them.
std::array<double, 3> QuarterCuts(const std::vector<double>& values) {
  auto at = [&](double q) { return values.empty() ? 0.0 : values[static_cast<std::size_t>(q * (values.size() - 1))]; };
  return {at(0.25), at(0.5), at(0.75)};
}

int QuarterOf(double v, const std::array<double, 3>& cut) {
  return v <= cut[0] ? 0 : v <= cut[1] ? 1 : v <= cut[2] ? 2 : 3;
}

// Best quarter green, then sky blue, orange, and the worst reddish purple.
cv::Scalar QuarterColour(int q) {
  static const std::array<std::size_t, 4> kColours = {2, 5, 4, 3};
  return PaletteColour(kColours[static_cast<std::size_t>(q)]);
}

std::string QuarterName(int q, const std::array<double, 3>& cut, const std::string& unit) {
  const std::string u = unit.empty() ? "" : " " + unit;
  if (q == 0) return fmt::format("<= {}{}", Readable(cut[0]), u);
  if (q == 3) return fmt::format("> {}{}", Readable(cut[2]), u);
  return fmt::format("{} - {}{}", Readable(cut[q - 1]), Readable(cut[q]), u);
}

namespace {

// The first objective's axis: the successful sets' range (sorted ascending), its top at most
// three interquartile ranges above the upper quartile, so a broken map's value does not flatten
// every other line (those above are drawn at the top and counted in the title).
AxisLimits ObjectiveAxis(const std::vector<double>& sorted_values) {
  double lo = sorted_values.empty() ? 0.0 : sorted_values.front();
  double hi = sorted_values.empty() ? 1.0 : sorted_values.back();
  const auto cut = QuarterCuts(sorted_values);
  const double fence = cut[2] + 3.0 * (cut[2] - cut[0]);
  if (fence > cut[2]) hi = std::min(hi, fence);
  if (!(hi > lo)) {
    const double band = std::max(std::abs(lo) * 0.1, 1e-6);
    lo -= band;
    hi += band;
  }
  const double pad = 0.04 * (hi - lo);
  return {lo - pad, hi + pad};
}

ParallelAxis AxisOfDimension(const optim::Dimension& d) {
  AxisLimits limits{d.lower, d.upper};
  if (!(d.upper > d.lower))
    limits = {d.lower - std::max(std::abs(d.lower) * 0.1, 0.5), d.lower + std::max(std::abs(d.lower) * 0.1, 0.5)};
  return {ShortParamName(d.name), ParamUnit(d.name), limits};
}

// A candidate's line: its values on each axis (NaN where it has none).
std::vector<double> LineValues(const optim::EvaluationRecord& r, const std::vector<optim::Dimension>& dims,
                               optim::Objective first) {
  std::vector<double> values;
  for (const auto& d : dims) values.push_back(SearchedValueOf(r, d.name).value_or(std::nan("")));
  values.push_back(r.status == optim::RunStatus::kOk ? optim::ValueOf(r, first) : std::nan(""));
  return values;
}

cv::Mat ParallelCoordinates(const optim::OptimizeResult& result, const FigureOptions& options) {
  const auto& dims = result.space.dimensions;
  const optim::Objective first = result.objectives.objectives()[0];
  const std::string objective = ObjectiveAt(result, 0).short_name;
  // Successful sets, worst first so the best are drawn on top.
  std::vector<const optim::EvaluationRecord*> ok;
  for (const auto& e : result.evaluations)
    if (e.status == optim::RunStatus::kOk) ok.push_back(&e);
  std::stable_sort(ok.begin(), ok.end(),
                   [&](const auto* a, const auto* b) { return optim::ValueOf(*a, first) > optim::ValueOf(*b, first); });
  std::vector<double> values;
  for (const auto* e : ok) values.push_back(optim::ValueOf(*e, first));
  std::sort(values.begin(), values.end());
  const auto cut = QuarterCuts(values);

  std::vector<ParallelAxis> axes;
  for (const auto& d : dims) axes.push_back(AxisOfDimension(d));
  axes.push_back({objective, "lower is better", ObjectiveAxis(values)});

  std::vector<ParallelLine> lines;
  for (const auto* e : ok)
    lines.push_back({LineValues(*e, dims, first), QuarterColour(QuarterOf(optim::ValueOf(*e, first), cut)), 1, false});
  std::vector<ParallelLegendEntry> legend;
  for (int q = 0; q < 4; ++q) legend.push_back({objective + " " + QuarterName(q, cut, ""), QuarterColour(q), 2});
  // The default, then the recommendation over it.
  bool clamped = false;
  for (const auto& [label, colour, thickness] :
       {std::tuple{"default", PaletteColour(6), 3}, std::tuple{"recommended", PaletteColour(1), 4}}) {
    const optim::Candidate* c = result.Find(label);
    if (c == nullptr) continue;
    ParallelLine line{LineValues(c->record, dims, first), colour, thickness, true};
    for (std::size_t a = 0; a < axes.size(); ++a)
      clamped = clamped || PlaceOnAxis(line.values[a], axes[a].limits).clamped;
    lines.push_back(std::move(line));
    legend.push_back({label, colour, thickness});
  }
  if (clamped) {
    legend.push_back({"a value beyond its axis: drawn at its end, the value written beside it", PaletteColour(6), 1,
                      LegendSample::kEndTriangle});
  }

  int above = 0;
  for (double v : values) above += v > axes.back().limits.upper ? 1 : 0;
  ParallelCoordinatesOptions o;
  o.width = 3 * options.panel.width + 4 * GridOptions{}.padding;  // as wide as a row of three panels
  o.height = options.panel.height + options.panel.height / 2;
  o.font_scale = options.panel.font_scale;
  const std::size_t failed = result.evaluations.size() - ok.size();
  o.title = fmt::format(
      "The {} successful parameter sets across the {} searched parameters, coloured by quarters of {} "
      "(lower is better, best on top){}{}",
      ok.size(), dims.size(), objective, failed > 0 ? fmt::format("; {} failed not shown", failed) : "",
      above > 0 ? fmt::format("; {} above the {} axis drawn at its top", above, objective) : "");
  return RenderParallelCoordinates(axes, lines, legend, o).image;
}

}  // namespace

cv::Mat ParameterSpaceFigure(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  switch (ParameterSpaceViewOf(result)) {
    case ParameterSpaceView::kNone: return {};
    case ParameterSpaceView::kSlices: return ObjectiveAgainstParameters(result, 0, options);
    case ParameterSpaceView::kScatterGrid: return ScatterGridFigure(result, options);
    case ParameterSpaceView::kParallelCoordinates: return ParallelCoordinates(result, options);
  }
  return {};
}

cv::Mat ObjectiveAgainstParameters(const optim::OptimizeResult& result, std::size_t k, const FigureOptions& options) {
  options.Validate();
  const auto& dims = result.space.dimensions;
  if (dims.empty() || result.evaluations.empty() || k >= result.objectives.size()) return {};
  const optim::Objective objective_id = result.objectives.objectives()[k];
  const std::string objective = ObjectiveAt(result, k).short_name;
  std::size_t successful = 0;
  for (const auto& e : result.evaluations) successful += e.status == optim::RunStatus::kOk ? 1 : 0;
  const auto limits = ObjectiveLimits(result);
  std::vector<cv::Mat> panels;
  int most_outside = 0;
  for (const auto& d : dims) {
    Series all = MakeSeries(fmt::format("evaluated sets ({})", successful), {}, {});
    all.colour = PaletteColour(5);
    all.marker = Marker::kCircle;
    all.marker_size = 6;
    int outside = 0;
    for (const auto& e : result.evaluations) {
      const auto x = SearchedValueOf(e, d.name);
      if (!x || e.status != optim::RunStatus::kOk) continue;
      const double v = optim::ValueOf(e, objective_id);
      all.x.push_back(*x);
      all.y.push_back(v);
      if (limits[k] && (v < limits[k]->lower || v > limits[k]->upper)) ++outside;
    }
    std::vector<Series> series = {all};
    AddCandidates(series, result, [&](const optim::Candidate& c) -> std::optional<std::pair<double, double>> {
      const auto x = SearchedValueOf(c.record, d.name);
      if (!x || c.record.status != optim::RunStatus::kOk) return std::nullopt;
      return std::pair{*x, optim::ValueOf(c.record, objective_id)};
    });
    PlotOptions o = options.panel.Plot();
    o.x_limits = SearchRangeAxis(d);
    o.y_limits = limits[k];
    o.x_label = DimensionTitle(d);
    o.y_label = ObjectiveAt(result, k).title;
    o.title = ShortParamName(d.name);
    o.legend = panels.empty();
    panels.push_back(RenderPlot(series, o).image);
    most_outside = std::max(most_outside, outside);
  }
  GridOptions g;
  g.columns = 3;
  g.title = fmt::format(
      "{} of every evaluated parameter set against each parameter (lower is better){}", objective,
      most_outside > 0 ? fmt::format("; {} of {} sets lie outside the axes", most_outside, successful) : "");
  return ComposeGrid(panels, g);
}

}  // namespace slamtune::report
