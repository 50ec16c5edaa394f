// Figures of the optimisation report (optimize_figures.h).
#include "slamtune/report/optimize_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {
namespace {

// The three projections of the objective space, as index pairs into the result's objectives.
constexpr std::array<std::pair<int, int>, 3> kProjections = {{{0, 1}, {0, 2}, {1, 2}}};

PlotOptions PanelOptions(const FigureOptions& f) {
  PlotOptions o;
  o.width = f.panel_width;
  o.height = f.panel_height;
  o.font_scale = f.font_scale;
  return o;
}

// The successful candidates' objective vectors (the failure score is never plotted).
std::vector<std::pair<const optim::Candidate*, std::vector<double>>> PlottableCandidates(
    const optim::OptimizeResult& result) {
  std::vector<std::pair<const optim::Candidate*, std::vector<double>>> out;
  for (const auto* c : CandidatesInReportOrder(result)) {
    if (c->record.status != "ok") continue;
    std::vector<double> objectives = result.objectives.Values(c->record);
    if (!result.objectives.IsFailureScore(objectives)) out.emplace_back(c, objectives);
  }
  return out;
}

// Valid individuals of a snapshot, and how many were left out.
std::pair<std::vector<std::vector<double>>, int> ValidIndividuals(const optim::GenerationSnapshot& snapshot,
                                                                   const optim::ObjectiveSet& objectives) {
  std::vector<std::vector<double>> valid;
  int failed = 0;
  for (const auto& v : snapshot.objectives) {
    if (objectives.IsFailureScore(v)) ++failed;
    else valid.push_back(v);
  }
  return {valid, failed};
}

// One group of points of a projection figure, and which of them are non-dominated.
struct PointGroup {
  std::string name;
  std::vector<std::vector<double>> points;
  std::vector<std::size_t> front;  // indices into points; drawn on top when mark_front
};

bool Inside(const std::optional<AxisLimits>& l, double v) { return !l || (v >= l->lower && v <= l->upper); }

// Scatter panels of the projections for the given point sets on the shared front-scaled axes,
// with the non-dominated points and the candidates on top. Each panel title says how many
// points lie outside its axes.
cv::Mat ProjectionPanels(const std::vector<PointGroup>& groups, const optim::OptimizeResult& result,
                         bool mark_candidates, bool mark_front, const FigureOptions& options, const std::string& title) {
  const auto limits = ObjectiveLimits(result);
  const auto candidates = PlottableCandidates(result);
  std::vector<cv::Mat> panels;
  for (const auto& [ix, iy] : kProjections) {
    std::vector<Series> series;
    Series front = MakeSeries("", {}, {});
    front.colour = PaletteColour(6);  // black
    front.marker = Marker::kDiamond;
    front.marker_size = 11;
    int outside = 0, total = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      Series s = MakeSeries(groups[g].name, {}, {});
      s.colour = groups.size() == 1 ? PaletteColour(5) : PaletteColour(g);
      s.marker = groups.size() == 1 ? Marker::kCircle : MarkerFor(g);
      s.marker_size = 7;
      for (const auto& v : groups[g].points) {
        s.x.push_back(v[ix]);
        s.y.push_back(v[iy]);
        ++total;
        if (!Inside(limits[ix], v[ix]) || !Inside(limits[iy], v[iy])) ++outside;
      }
      for (std::size_t i : groups[g].front) {
        front.x.push_back(groups[g].points[i][ix]);
        front.y.push_back(groups[g].points[i][iy]);
      }
      series.push_back(std::move(s));
    }
    if (mark_front) {
      front.name = fmt::format("non-dominated ({})", front.x.size());
      series.push_back(std::move(front));
    }
    if (mark_candidates) {
      for (const auto& [c, v] : candidates) series.push_back(CandidateSeries(*c, v[ix], v[iy]));
    }
    PlotOptions o = PanelOptions(options);
    o.x_limits = limits[ix];
    o.y_limits = limits[iy];
    o.x_label = ObjectiveAt(result, ix).title;
    o.y_label = ObjectiveAt(result, iy).title;
    o.title = fmt::format("{} vs {}", ObjectiveAt(result, iy).short_name, ObjectiveAt(result, ix).short_name);
    if (outside > 0) o.title += fmt::format(" ({} of {} outside)", outside, total);
    o.legend = panels.empty();  // one legend is enough for the row
    panels.push_back(RenderPlot(series, o).image);
  }
  GridOptions g;
  g.columns = 3;
  g.title = title;
  return ComposeGrid(panels, g);
}

std::string FailedNote(int failed) {
  return failed == 0 ? "" : fmt::format(" ({} failed run{} not shown)", failed, failed == 1 ? "" : "s");
}

}  // namespace

void FigureOptions::Validate() const {
  if (panel_width < 160) throw InputError(fmt::format("FigureOptions.panel_width = {}: must be >= 160 px", panel_width));
  if (panel_height < 120) {
    throw InputError(fmt::format("FigureOptions.panel_height = {}: must be >= 120 px", panel_height));
  }
  if (!(font_scale > 0.0 && font_scale <= 4.0)) {
    throw InputError(fmt::format("FigureOptions.font_scale = {}: must be in (0, 4]", font_scale));
  }
  maps.Validate();
}

Series CandidateSeries(const optim::Candidate& candidate, double x, double y) {
  Series s = MakeSeries(candidate.label, {x}, {y});
  const std::string& l = candidate.label;
  // Fixed per label, distinct from the population's blue circles.
  if (l == "recommended") {
    s.colour = PaletteColour(1);  // vermillion
    s.marker = Marker::kStar;
    s.marker_size = 18;
  } else if (l == "knee") {
    s.colour = PaletteColour(2);  // bluish green
    s.marker = Marker::kDiamond;
    s.marker_size = 16;
  } else if (l == "default") {
    s.colour = PaletteColour(6);  // black
    s.marker = Marker::kSquare;
    s.marker_size = 14;
  } else if (l == "worst") {
    s.colour = PaletteColour(3);  // reddish purple
    s.marker = Marker::kCross;
    s.marker_size = 14;
  } else {
    s.colour = PaletteColour(4);  // orange
    s.marker = Marker::kPlus;
    s.marker_size = 14;
  }
  return s;
}

std::vector<std::optional<AxisLimits>> ObjectiveLimits(const optim::OptimizeResult& result) {
  const std::size_t m = result.objectives.size();
  std::vector<std::vector<double>> all;
  for (const auto& snapshot : result.snapshots) {
    for (auto& v : ValidIndividuals(snapshot, result.objectives).first) all.push_back(std::move(v));
  }
  std::vector<std::vector<double>> shown;  // the front of every snapshot together, and the chosen sets
  for (std::size_t i : optim::NonDominatedIndices(all)) shown.push_back(all[i]);
  for (const auto& [c, v] : PlottableCandidates(result)) {
    if (c->label == "recommended" || c->label == "knee") shown.push_back(v);
  }
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> lo(m, inf), hi(m, -inf), most(m, -inf);
  for (const auto& v : shown) {
    for (std::size_t k = 0; k < m && k < v.size(); ++k) {
      if (!std::isfinite(v[k])) continue;
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  }
  for (const auto& v : all)
    for (std::size_t k = 0; k < m && k < v.size(); ++k)
      if (std::isfinite(v[k])) most[k] = std::max(most[k], v[k]);
  std::vector<std::optional<AxisLimits>> out(m);
  for (std::size_t k = 0; k < m; ++k) {
    if (lo[k] > hi[k]) continue;
    double range = hi[k] - lo[k];
    if (!(range > 0.0)) range = std::max(std::abs(lo[k]) * 0.1, 1e-6);  // a single value: a band around it
    // Up to one front range beyond the front's worst values, where the population still is.
    const double upper = std::max(hi[k], std::min(most[k], hi[k] + range));
    const double pad = 0.08 * (upper - lo[k] > 0.0 ? upper - lo[k] : range);  // extreme points off the frame
    out[k] = AxisLimits{lo[k] - pad, upper + pad};
  }
  return out;
}

std::vector<CandidateMapPanel> CandidateMapPanels(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  std::vector<CandidateMapPanel> out;
  for (CandidateGroup& group : MergedCandidates(result)) {
    const optim::Candidate& c = group.shown();
    std::string caption = ParamSummary(c.record.params, result.space);
    if (c.record.status == "ok") {
      caption += fmt::format(", {} loop closure{}", c.record.loop_closures, c.record.loop_closures == 1 ? "" : "s");
    } else {
      caption += ", run failed";
    }
    MapOverlay overlay;
    for (const auto& [x, y] : c.path) overlay.path.emplace_back(x, y);
    for (const optim::LoopEdge& e : c.loop_edges) {
      overlay.segments.push_back({e.from_x, e.from_y, e.to_x, e.to_y, e.log_index >= 0 ? std::to_string(e.log_index) : ""});
    }
    cv::Mat image = RenderMapPanel(c.map, group.label, caption, options.maps, overlay);
    out.push_back({std::move(group), std::move(image)});
  }
  return out;
}

cv::Mat MapsSideBySide(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  SLAMTUNE_CHECK_MSG(!result.candidates.empty(), "MapsSideBySide needs at least one candidate");
  std::vector<cv::Mat> panels;
  for (auto& p : CandidateMapPanels(result, options)) panels.push_back(std::move(p.image));
  GridOptions g;
  g.columns = 2;
  g.title = "Maps of the candidates (loop closures in vermillion)";
  return ComposeGrid(panels, g);
}

cv::Mat PopulationFigure(const optim::GenerationSnapshot& snapshot, const optim::OptimizeResult& result,
                         const FigureOptions& options) {
  options.Validate();
  auto [valid, failed] = ValidIndividuals(snapshot, result.objectives);
  PointGroup group{fmt::format("population ({})", valid.size()), std::move(valid), {}};
  group.front = optim::NonDominatedIndices(group.points);
  return ProjectionPanels({group}, result, true, true, options,
                          fmt::format("Generation {}: population in objective space, axes on the front{}",
                                      snapshot.generation, FailedNote(failed)));
}

cv::Mat PopulationEvolutionFigure(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  std::vector<PointGroup> groups;
  int failed = 0;
  for (const auto& snapshot : result.snapshots) {
    auto [valid, f] = ValidIndividuals(snapshot, result.objectives);
    failed += f;
    groups.push_back({fmt::format("generation {}", snapshot.generation), std::move(valid), {}});
  }
  if (groups.empty()) groups.push_back({"no snapshots", {}, {}});
  return ProjectionPanels(groups, result, false, false, options,
                          "Population over the generations, axes on the front" + FailedNote(failed));
}

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

cv::Mat ParameterSpaceFigure(const optim::OptimizeResult& result, const FigureOptions& options) {
  options.Validate();
  const auto& dims = result.space.dimensions;
  if (dims.empty() || result.evaluations.empty() || result.objectives.size() == 0) return {};
  const optim::Objective first = result.objectives.objectives()[0];
  const std::string objective = ObjectiveAt(result, 0).short_name;
  std::vector<double> values;
  for (const auto& e : result.evaluations)
    if (e.status == "ok") values.push_back(optim::ValueOf(e, first));
  std::sort(values.begin(), values.end());

  if (dims.size() == 2) {
    // Quarters of the first objective over the successful sets.
    auto quantile = [&](double q) { return values.empty() ? 0.0 : values[static_cast<std::size_t>(q * (values.size() - 1))]; };
    const std::array<double, 3> cut = {quantile(0.25), quantile(0.5), quantile(0.75)};
    const std::array<std::size_t, 4> colours = {2, 5, 4, 3};  // green, sky blue, orange, purple
    std::vector<Series> series;
    for (int q = 0; q < 4; ++q) {
      const std::string range = q == 0   ? fmt::format("<= {}", Readable(cut[0]))
                                : q == 3 ? fmt::format("> {}", Readable(cut[2]))
                                         : fmt::format("{}-{}", Readable(cut[q - 1]), Readable(cut[q]));
      Series s = MakeSeries(fmt::format("{} {}", objective, range), {}, {});
      s.colour = PaletteColour(colours[q]);
      s.marker = Marker::kCircle;
      s.marker_size = 8;
      series.push_back(std::move(s));
    }
    Series failed = MakeSeries("failed run", {}, {});
    failed.colour = cv::Scalar(150, 150, 150);
    failed.marker = Marker::kCross;
    failed.marker_size = 8;
    for (const auto& e : result.evaluations) {
      const auto x = ParamOf(e, dims[0].name), y = ParamOf(e, dims[1].name);
      if (!x || !y) continue;
      Series* s = &failed;
      if (e.status == "ok") {
        const double v = optim::ValueOf(e, first);
        const int q = v <= cut[0] ? 0 : v <= cut[1] ? 1 : v <= cut[2] ? 2 : 3;
        s = &series[static_cast<std::size_t>(q)];
      }
      s->x.push_back(*x);
      s->y.push_back(*y);
    }
    if (!failed.x.empty()) series.push_back(std::move(failed));
    AddCandidates(series, result, [&](const optim::Candidate& c) -> std::optional<std::pair<double, double>> {
      const auto x = ParamOf(c.record, dims[0].name), y = ParamOf(c.record, dims[1].name);
      if (!x || !y) return std::nullopt;
      return std::pair{*x, *y};
    });
    PlotOptions o = PanelOptions(options);
    o.width = 2 * options.panel_width;
    o.height = options.panel_height + options.panel_height / 2;
    o.x_limits = BoundsOf(dims[0]);
    o.y_limits = BoundsOf(dims[1]);
    o.x_label = DimensionTitle(dims[0]);
    o.y_label = DimensionTitle(dims[1]);
    o.title = fmt::format("The {} evaluated parameter sets, coloured by {} (quarters, lower is better)",
                          result.evaluations.size(), objective);
    return RenderPlot(series, o).image;
  }

  return ObjectiveAgainstParameters(result, 0, options);
}

cv::Mat ObjectiveAgainstParameters(const optim::OptimizeResult& result, std::size_t k, const FigureOptions& options) {
  options.Validate();
  const auto& dims = result.space.dimensions;
  if (dims.empty() || result.evaluations.empty() || k >= result.objectives.size()) return {};
  const optim::Objective objective_id = result.objectives.objectives()[k];
  const std::string objective = ObjectiveAt(result, k).short_name;
  std::size_t successful = 0;
  for (const auto& e : result.evaluations) successful += e.status == "ok" ? 1 : 0;
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
      if (!x || e.status != "ok") continue;
      const double v = optim::ValueOf(e, objective_id);
      all.x.push_back(*x);
      all.y.push_back(v);
      if (limits[k] && (v < limits[k]->lower || v > limits[k]->upper)) ++outside;
    }
    std::vector<Series> series = {all};
    AddCandidates(series, result, [&](const optim::Candidate& c) -> std::optional<std::pair<double, double>> {
      const auto x = ParamOf(c.record, d.name);
      if (!x || c.record.status != "ok") return std::nullopt;
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
  g.title = fmt::format("{} of every evaluated parameter set against each parameter (lower is better){}", objective,
                        most_outside > 0 ? fmt::format("; {} of {} sets lie outside the axes", most_outside, successful)
                                         : "");
  return ComposeGrid(panels, g);
}

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
  PlotOptions o = PanelOptions(options);
  o.width = 3 * options.panel_width;
  o.x_label = "seconds into the log";
  o.y_label = "sequential match response";
  o.y_limits = AxisLimits{0.0, 1.0};
  o.title = "The base configuration's front end along the log";
  return RenderPlot({all, edge, broke}, o).image;
}

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
    PlotOptions o = PanelOptions(options);
    o.x_limits = x_limits;
    o.x_label = "generation";
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
  PlotOptions o = PanelOptions(options);
  o.x_limits = x_limits;
  o.y_limits = AxisLimits{0.0, std::pow(optim::kHypervolumeReference, static_cast<double>(result.objectives.size()))};
  o.x_label = "generation";
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

cv::Mat ObjectiveVsErrorFigure(const std::vector<optim::EvaluationRecord>& runs,
                               const ErrorCorrelationSummary& correlation, const optim::OptimizeResult& result,
                               const FigureOptions& options) {
  options.Validate();
  std::vector<cv::Mat> panels;
  for (std::size_t k = 0; k < result.objectives.size(); ++k) {
    Series all = MakeSeries(fmt::format("parameter sets ({})", runs.size()), {}, {});
    all.colour = PaletteColour(0);
    all.marker = Marker::kCircle;
    all.marker_size = 7;
    for (const auto& r : runs) {
      all.x.push_back(optim::ValueOf(r, result.objectives.objectives()[k]));
      all.y.push_back(r.trans_mean_m);
    }
    std::vector<Series> series = {all};
    for (const auto* c : CandidatesInReportOrder(result)) {
      if (c->record.status == "ok" && c->record.has_gt) {
        series.push_back(CandidateSeries(*c, optim::ValueOf(c->record, result.objectives.objectives()[k]),
                                         c->record.trans_mean_m));
      }
    }
    PlotOptions o = PanelOptions(options);
    o.x_label = ObjectiveAt(result, k).title;
    o.y_label = "mean translational error (m)";
    const RankCorrelation* s = k < correlation.objectives.size() ? &correlation.objectives[k].spearman : nullptr;
    const char* name = ObjectiveAt(result, k).short_name;
    o.title = s && s->defined ? fmt::format("{}: Spearman rho = {:.2f}", name, s->rho)
                              : fmt::format("{}: rho undefined", name);
    o.legend = k == 0;
    panels.push_back(RenderPlot(series, o).image);
  }
  GridOptions g;
  g.columns = 3;
  g.title = "Objectives against the ground-truth translational error";
  return ComposeGrid(panels, g);
}

}  // namespace slamtune::report
