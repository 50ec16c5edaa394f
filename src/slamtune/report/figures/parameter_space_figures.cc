// Where the search went in parameter space: the scatter grid of two searched parameters, parallel
// coordinates of more, and the slices of one objective against each parameter (optimize_figures.h).
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
#include "slamtune/report/report_text.h"

namespace slamtune::report {

namespace {

std::optional<double> ParamOf(const optim::EvaluationRecord& r, const std::string& name) {
  const auto it = r.params.find(name);
  if (it == r.params.end() || !std::isfinite(it->second)) return std::nullopt;
  return it->second;
}

AxisLimits BoundsOf(const optim::Dimension& d) {
  const double range = d.upper > d.lower ? d.upper - d.lower : std::max(std::abs(d.lower), 1.0);
  return {d.lower - 0.04 * range, (d.upper > d.lower ? d.upper : d.lower + range) + 0.04 * range};
}

std::string DimensionTitle(const optim::Dimension& d) {
  const std::string s = ShortParamName(d.name);
  return s == d.name ? d.name : s + " = " + d.name;
}

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
  const AxisLimits search = BoundsOf(dimension);
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
    if (const auto x = ParamOf(c->record, p.x->name)) xs.push_back(*x);
    if (const auto y = ParamOf(c->record, p.y->name)) ys.push_back(*y);
  }
  p.x_limits = ParameterAxisLimits(*p.x, xs);
  p.y_limits = ParameterAxisLimits(*p.y, ys);
  const AxisLimits bx = BoundsOf(*p.x), by = BoundsOf(*p.y);
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
  const auto x = ParamOf(r, pair.x->name), y = ParamOf(r, pair.y->name);
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
  PlotOptions o = PanelOptions(options);
  o.x_limits = pair.x_limits;
  o.y_limits = pair.y_limits;
  o.x_label = DimensionTitle(*pair.x) + UnitSuffix(ParamUnit(pair.x->name));
  o.y_label = DimensionTitle(*pair.y) + UnitSuffix(ParamUnit(pair.y->name));
  o.title = groups.title;
  return RenderPlot(series, o).image;
}

cv::Mat ScatterGrid(const optim::OptimizeResult& result, const FigureOptions& options) {
  const SpacePair pair = PairOf(result);
  const std::vector<Series> shared = SharedSeries(result, pair);
  const std::vector<SpacePanel> panels = ParameterSpacePanels(result);
  std::vector<cv::Mat> images;
  for (const SpacePanel& p : panels) images.push_back(ScatterPanel(p, result, pair, shared, options));
  PlotOptions legend = PanelOptions(options);
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
  for (const auto& d : dims) values.push_back(ParamOf(r, d.name).value_or(std::nan("")));
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
  o.width = 3 * options.panel_width + 4 * GridOptions{}.padding;  // as wide as a row of three panels
  o.height = options.panel_height + options.panel_height / 2;
  o.font_scale = options.font_scale;
  const std::size_t failed = result.evaluations.size() - ok.size();
  o.title = fmt::format(
      "The {} successful parameter sets across the {} searched parameters, coloured by quarters of {} "
      "(lower is better, best on top){}{}",
      ok.size(), dims.size(), objective, failed > 0 ? fmt::format("; {} failed not shown", failed) : "",
      above > 0 ? fmt::format("; {} above the {} axis drawn at its top", above, objective) : "");
  return RenderParallelCoordinates(axes, lines, legend, o).image;
}

}  // namespace

std::vector<Series> ScatterGridCandidates(const optim::OptimizeResult& result) {
  if (result.space.dimensions.size() != 2) return {};
  return PairCandidates(result, PairOf(result));
}

cv::Mat ParameterSpaceFigure(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  switch (ParameterSpaceViewOf(result)) {
    case ParameterSpaceView::kNone: return {};
    case ParameterSpaceView::kSlices: return ObjectiveAgainstParameters(result, 0, options);
    case ParameterSpaceView::kScatterGrid: return ScatterGrid(result, options);
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
      const auto x = ParamOf(e, d.name);
      if (!x || e.status != optim::RunStatus::kOk) continue;
      const double v = optim::ValueOf(e, objective_id);
      all.x.push_back(*x);
      all.y.push_back(v);
      if (limits[k] && (v < limits[k]->lower || v > limits[k]->upper)) ++outside;
    }
    std::vector<Series> series = {all};
    AddCandidates(series, result, [&](const optim::Candidate& c) -> std::optional<std::pair<double, double>> {
      const auto x = ParamOf(c.record, d.name);
      if (!x || c.record.status != optim::RunStatus::kOk) return std::nullopt;
      return std::pair{*x, optim::ValueOf(c.record, objective_id)};
    });
    PlotOptions o = PanelOptions(options);
    o.x_limits = BoundsOf(d);
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
