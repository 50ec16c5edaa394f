// The scatter grid of parameter_space.png, the view of two searched parameters (optimize_figures.h):
// the evaluated sets in the plane of the pair, coloured once per panel (ParameterSpacePanels), the
// candidates and failed runs in every panel, and a last panel for what they share.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
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

std::vector<SpacePanel> ParameterSpacePanels(const optim::OptimizeResult& result) {
  std::vector<SpacePanel> panels;
  for (std::size_t k = 0; k < result.objectives.size(); ++k) panels.push_back({SpaceColouring::kObjective, k});
  panels.push_back({SpaceColouring::kLoopClosures, 0});
  const bool ground_truth =
      std::any_of(result.evaluations.begin(), result.evaluations.end(),
                  [](const optim::EvaluationRecord& e) { return e.status == optim::RunStatus::kOk && e.has_gt; });
  if (ground_truth) panels.push_back({SpaceColouring::kTranslationalError, 0});
  return panels;
}

std::vector<CountClass> LoopClosureClasses(std::vector<int> counts, std::size_t max_classes) {
  SLAMTUNE_CHECK(max_classes >= 1);
  std::vector<CountClass> classes;
  if (counts.empty()) return classes;
  std::sort(counts.begin(), counts.end());
  std::vector<int> distinct = counts;
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() <= max_classes) {
    for (int c : distinct) classes.push_back({c, c});
    return classes;
  }
  // Each class ends at the count below which about (i + 1) / max_classes of the sets lie.
  int lower = counts.front();
  for (std::size_t i = 0; i < max_classes; ++i) {
    const std::size_t end = std::max<std::size_t>((i + 1) * counts.size() / max_classes, 1);
    const int upper = counts[end - 1];
    if (upper < lower) continue;  // this share lies inside the previous class
    classes.push_back({lower, upper});
    lower = upper + 1;
  }
  if (classes.back().upper < counts.back()) classes.back().upper = counts.back();
  return classes;
}

AxisLimits ParameterAxisLimits(const optim::Dimension& dimension, const std::vector<double>& marked) {
  const AxisLimits search = SearchRangeAxis(dimension);
  const double span = search.upper - search.lower;
  AxisLimits out = search;
  for (double v : marked) {
    if (!std::isfinite(v)) continue;
    const AxisLimits wider{std::min(out.lower, v - 0.04 * span), std::max(out.upper, v + 0.04 * span)};
    if (wider.upper - wider.lower <= 2.0 * span) out = wider;  // the search range keeps half the axis
  }
  return out;
}

namespace {

// A colour of a dark-to-light ramp (viridis, stopping short of its pale yellow end), t in [0, 1].
cv::Scalar RampColour(double t) {
  cv::Mat grey(1, 1, CV_8UC1, cv::Scalar(std::lround(std::clamp(t, 0.0, 1.0) * 0.85 * 255.0)));
  cv::Mat colour;
  cv::applyColorMap(grey, colour, cv::COLORMAP_VIRIDIS);
  const cv::Vec3b c = colour.at<cv::Vec3b>(0, 0);
  return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
}

std::string UnitSuffix(const std::string& unit) { return unit.empty() ? "" : " (" + unit + ")"; }

// The varied pair of the scatter grid, with the axes every panel shares.
struct SpacePair {
  const optim::Dimension* x = nullptr;
  const optim::Dimension* y = nullptr;
  AxisLimits x_limits, y_limits;
  bool widened = false;  // an axis goes beyond the search range to hold a candidate
};

SpacePair PairOf(const optim::OptimizeResult& result) {
  SpacePair p{&result.space.dimensions[0], &result.space.dimensions[1], {}, {}, false};
  std::vector<double> xs, ys;
  for (const auto* c : CandidatesInReportOrder(result)) {
    if (const auto x = SearchedValueOf(c->record, p.x->name)) xs.push_back(*x);
    if (const auto y = SearchedValueOf(c->record, p.y->name)) ys.push_back(*y);
  }
  p.x_limits = ParameterAxisLimits(*p.x, xs);
  p.y_limits = ParameterAxisLimits(*p.y, ys);
  const AxisLimits bx = SearchRangeAxis(*p.x), by = SearchRangeAxis(*p.y);
  p.widened = p.x_limits.lower < bx.lower || p.x_limits.upper > bx.upper || p.y_limits.lower < by.lower ||
              p.y_limits.upper > by.upper;
  return p;
}

// Where a set of the pair is drawn: at its values, or just inside the border (so the whole
// marker shows) along an axis it lies outside of.
struct PairPoint {
  double x = 0.0, y = 0.0;
  bool x_outside = false, y_outside = false;
  bool outside() const { return x_outside || y_outside; }
};

std::optional<PairPoint> PointOf(const optim::EvaluationRecord& r, const SpacePair& pair) {
  const auto x = SearchedValueOf(r, pair.x->name), y = SearchedValueOf(r, pair.y->name);
  if (!x || !y) return std::nullopt;
  auto inside = [](double v, const AxisLimits& l, bool& outside) {
    const AxisPlacement p = PlaceOnAxis(v, l);
    outside = p.clamped;
    if (!p.clamped) return p.value;
    const double nudge = 0.02 * (l.upper - l.lower);
    return p.value >= l.upper ? l.upper - nudge : l.lower + nudge;
  };
  PairPoint p;
  p.x = inside(*x, pair.x_limits, p.x_outside);
  p.y = inside(*y, pair.y_limits, p.y_outside);
  return p;
}

// The candidates' markers on the pair's axes (ScatterGridCandidates): a grey triangle behind
// each one outside the axes, then the candidates' own markers.
std::vector<Series> PairCandidates(const optim::OptimizeResult& result, const SpacePair& pair) {
  std::vector<Series> outside, marks;
  for (const CandidateGroup& g : MergedCandidates(result)) {
    for (const auto* c : g.members) {
      const auto p = PointOf(c->record, pair);
      if (!p) continue;
      Series s = CandidateSeries(*c, p->x, p->y);
      if (p->outside()) {
        // Only the values that lie outside, so the legend stays narrow.
        std::string where;
        if (p->x_outside) where = ShortParamName(pair.x->name) + "=" + FormatParam(c->record.params.at(pair.x->name));
        if (p->y_outside) {
          where += (where.empty() ? "" : " ") + ShortParamName(pair.y->name) + "=" +
                   FormatParam(c->record.params.at(pair.y->name));
        }
        s.name += " (" + where + ": outside)";
        Series t = MakeSeries(outside.empty() ? "outside the axes: at the border" : "", {p->x}, {p->y});
        t.colour = cv::Scalar(140, 140, 140);
        t.marker = Marker::kTriangle;
        t.marker_size = 26;
        outside.push_back(std::move(t));
      }
      marks.push_back(std::move(s));
    }
  }
  outside.insert(outside.end(), marks.begin(), marks.end());
  return outside;
}

// The search range's outline, when an axis was widened beyond it.
Series SearchRangeOutline(const SpacePair& pair) {
  const double x0 = pair.x->lower, x1 = pair.x->upper, y0 = pair.y->lower, y1 = pair.y->upper;
  Series s = MakeSeries("search range", {x0, x1, x1, x0, x0}, {y0, y0, y1, y1, y0}, SeriesStyle::kLine);
  s.colour = cv::Scalar(160, 160, 160);
  return s;
}

// One scatter panel's coloured groups of the successful sets.
struct ColouredGroups {
  std::vector<Series> series;
  std::string title;
};

// Quarters of `value` over the successful sets it is defined for.
ColouredGroups QuarterGroups(const optim::OptimizeResult& result, const SpacePair& pair,
                             const std::function<std::optional<double>(const optim::EvaluationRecord&)>& value,
                             const std::string& unit) {
  std::vector<double> values;
  for (const auto& e : result.evaluations)
    if (const auto v = value(e)) values.push_back(*v);
  std::sort(values.begin(), values.end());
  const auto cut = QuarterCuts(values);
  ColouredGroups g;
  for (int q = 0; q < 4; ++q) {
    Series s = MakeSeries(QuarterName(q, cut, unit), {}, {});
    s.colour = QuarterColour(q);
    s.marker = Marker::kCircle;
    s.marker_size = 8;
    g.series.push_back(std::move(s));
  }
  for (const auto& e : result.evaluations) {
    const auto v = value(e);
    const auto p = PointOf(e, pair);
    if (!v || !p) continue;
    Series& s = g.series[static_cast<std::size_t>(QuarterOf(*v, cut))];
    s.x.push_back(p->x);
    s.y.push_back(p->y);
  }
  return g;
}

ColouredGroups LoopGroups(const optim::OptimizeResult& result, const SpacePair& pair) {
  std::vector<int> counts;
  for (const auto& e : result.evaluations)
    if (e.status == optim::RunStatus::kOk) counts.push_back(e.loop_closures);
  const std::vector<CountClass> classes = LoopClosureClasses(counts, 6);
  ColouredGroups g;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const CountClass& c = classes[i];
    const std::string range = c.lower == c.upper ? std::to_string(c.lower) : fmt::format("{} - {}", c.lower, c.upper);
    Series s = MakeSeries(fmt::format("{} loop closure{}", range, c.upper == 1 && c.lower == 1 ? "" : "s"), {}, {});
    s.colour = RampColour(classes.size() == 1 ? 0.5 : static_cast<double>(i) / (classes.size() - 1));
    s.marker = Marker::kCircle;
    s.marker_size = 8;
    g.series.push_back(std::move(s));
  }
  for (const auto& e : result.evaluations) {
    const auto p = PointOf(e, pair);
    if (e.status != optim::RunStatus::kOk || !p) continue;
    for (std::size_t i = 0; i < classes.size(); ++i) {
      if (e.loop_closures < classes[i].lower || e.loop_closures > classes[i].upper) continue;
      g.series[i].x.push_back(p->x);
      g.series[i].y.push_back(p->y);
    }
  }
  g.title = "by loop closures";
  return g;
}

ColouredGroups GroupsFor(const SpacePanel& panel, const optim::OptimizeResult& result, const SpacePair& pair) {
  switch (panel.colouring) {
    case SpaceColouring::kObjective: {
      const optim::Objective id = result.objectives.objectives()[panel.objective];
      ColouredGroups g = QuarterGroups(
          result, pair,
          [&](const optim::EvaluationRecord& e) -> std::optional<double> {
            if (e.status != optim::RunStatus::kOk) return std::nullopt;
            return optim::ValueOf(e, id);
          },
          "");
      g.title = fmt::format("by {} (quarters, lower is better)", ObjectiveAt(result, panel.objective).short_name);
      return g;
    }
    case SpaceColouring::kLoopClosures: return LoopGroups(result, pair);
    case SpaceColouring::kTranslationalError: {
      ColouredGroups g = QuarterGroups(
          result, pair,
          [](const optim::EvaluationRecord& e) -> std::optional<double> {
            if (e.status != optim::RunStatus::kOk || !e.has_gt || !std::isfinite(e.trans_mean_m)) return std::nullopt;
            return e.trans_mean_m;
          },
          "m");
      g.title = "by the true translational error (quarters)";
      return g;
    }
  }
  return {};
}

Series FailedRuns(const optim::OptimizeResult& result, const SpacePair& pair) {
  Series failed = MakeSeries("failed run", {}, {});
  failed.colour = cv::Scalar(150, 150, 150);
  failed.marker = Marker::kCross;
  failed.marker_size = 8;
  for (const auto& e : result.evaluations) {
    const auto p = PointOf(e, pair);
    if (e.status == optim::RunStatus::kOk || !p) continue;
    failed.x.push_back(p->x);
    failed.y.push_back(p->y);
  }
  return failed;
}

// What every panel of the grid draws the same way: the search range's outline (when an axis
// was widened), failed runs and the candidates' markers. Listed once, in the legend panel.
std::vector<Series> SharedSeries(const optim::OptimizeResult& result, const SpacePair& pair) {
  std::vector<Series> shared;
  if (pair.widened) shared.push_back(SearchRangeOutline(pair));
  if (Series failed = FailedRuns(result, pair); !failed.x.empty()) {
    failed.name = fmt::format("failed run ({})", failed.x.size());
    shared.push_back(std::move(failed));
  }
  for (Series& c : PairCandidates(result, pair)) shared.push_back(std::move(c));
  return shared;
}

// One panel: the coloured groups (listed best first in its legend, drawn worst first so the
// best lie on top), then the shared series without names.
cv::Mat ScatterPanel(const SpacePanel& panel, const optim::OptimizeResult& result, const SpacePair& pair,
                     const std::vector<Series>& shared, const FigureOptions& options) {
  ColouredGroups groups = GroupsFor(panel, result, pair);
  std::vector<Series> series;
  for (const Series& s : shared) {
    if (s.style != SeriesStyle::kLine) continue;  // the outline under the points
    series.push_back(s);
    series.back().name.clear();
  }
  for (auto it = groups.series.rbegin(); it != groups.series.rend(); ++it) {
    Series points = *it;
    points.name.clear();
    series.push_back(std::move(points));
  }
  for (Series& s : groups.series) {
    if (s.x.empty()) continue;  // an empty quarter (tied values) or class is not listed
    s.x.clear();
    s.y.clear();
    series.push_back(std::move(s));
  }
  for (const Series& s : shared) {
    if (s.style == SeriesStyle::kLine) continue;
    series.push_back(s);
    series.back().name.clear();
  }
  PlotOptions o = options.panel.Plot();
  o.x_limits = pair.x_limits;
  o.y_limits = pair.y_limits;
  o.x_label = DimensionTitle(*pair.x) + UnitSuffix(ParamUnit(pair.x->name));
  o.y_label = DimensionTitle(*pair.y) + UnitSuffix(ParamUnit(pair.y->name));
  o.title = groups.title;
  return RenderPlot(series, o).image;
}

}  // namespace

cv::Mat ScatterGridFigure(const optim::OptimizeResult& result, const FigureOptions& options) {
  const SpacePair pair = PairOf(result);
  const std::vector<Series> shared = SharedSeries(result, pair);
  const std::vector<SpacePanel> panels = ParameterSpacePanels(result);
  std::vector<cv::Mat> images;
  for (const SpacePanel& p : panels) images.push_back(ScatterPanel(p, result, pair, shared, options));
  PlotOptions legend = options.panel.Plot();
  legend.title = "In every panel";
  images.push_back(RenderLegend(shared, legend));
  GridOptions g;
  g.columns = 3;
  g.title = fmt::format("The {} evaluated parameter sets in ({}, {}), coloured {}", result.evaluations.size(),
                        ShortParamName(pair.x->name), ShortParamName(pair.y->name),
                        panels.size() > result.objectives.size() + 1 ? "by each objective, loop closures and true error"
                                                                     : "by each objective and by loop closures");
  return ComposeGrid(images, g);
}

std::vector<Series> ScatterGridCandidates(const optim::OptimizeResult& result) {
  if (result.space.dimensions.size() != 2) return {};
  return PairCandidates(result, PairOf(result));
}

}  // namespace slamtune::report
