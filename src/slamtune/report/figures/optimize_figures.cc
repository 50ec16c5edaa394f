// The figures of the optimisation report in objective space: the candidates' maps, the population
// and its evolution, the objectives against the true error; and what every figure shares
// (optimize_figures.h).
#include "slamtune/report/figures/optimize_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <tuple>

#include "slamtune/common/error.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {
namespace {

// The three projections of the objective space, as index pairs into the result's objectives.
constexpr std::array<std::pair<int, int>, 3> kProjections = {{{0, 1}, {0, 2}, {1, 2}}};

// The successful candidates' objective vectors (the failure score is never plotted).
std::vector<std::pair<const optim::Candidate*, std::vector<double>>> PlottableCandidates(
    const optim::OptimizeResult& result) {
  std::vector<std::pair<const optim::Candidate*, std::vector<double>>> out;
  for (const auto* c : CandidatesInReportOrder(result)) {
    if (c->record.status != optim::RunStatus::kOk) continue;
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
    if (objectives.IsFailureScore(v))
      ++failed;
    else
      valid.push_back(v);
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
                         bool mark_candidates, bool mark_front, const FigureOptions& options,
                         const std::string& title) {
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
    PlotOptions o = options.panel.Plot();
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
  panel.Validate("FigureOptions.panel");
  maps.Validate();
}

Series CandidateSeries(const optim::Candidate& candidate, double x, double y) {
  struct LabelStyle {
    const char* label;
    int colour;  // PaletteColour index
    Marker marker;
    int marker_size;
  };
  // Fixed per label, distinct from the population's blue circles; the last row is any other label.
  static constexpr LabelStyle kStyles[] = {
      {"recommended", 1, Marker::kStar, 18},  // vermillion
      {"knee", 2, Marker::kDiamond, 16},      // bluish green
      {"default", 6, Marker::kSquare, 14},    // black
      {"worst", 3, Marker::kCross, 14},       // reddish purple
      {"", 4, Marker::kPlus, 14},             // orange
  };
  const LabelStyle* style = std::begin(kStyles);
  while (style + 1 != std::end(kStyles) && candidate.label != style->label) ++style;
  Series s = MakeSeries(candidate.label, {x}, {y});
  s.colour = PaletteColour(style->colour);
  s.marker = style->marker;
  s.marker_size = style->marker_size;
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
    if (c.record.status == optim::RunStatus::kOk) {
      caption += fmt::format(", {} loop closure{}", c.record.loop_closures, c.record.loop_closures == 1 ? "" : "s");
    } else {
      caption += ", run failed";
    }
    MapOverlay overlay;
    for (const auto& [x, y] : c.path) overlay.path.emplace_back(x, y);
    for (const optim::LoopEdge& e : c.loop_edges) {
      overlay.segments.push_back(
          {e.from_x, e.from_y, e.to_x, e.to_y, e.log_index >= 0 ? std::to_string(e.log_index) : ""});
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
      if (c->record.status == optim::RunStatus::kOk && c->record.has_gt) {
        series.push_back(
            CandidateSeries(*c, optim::ValueOf(c->record, result.objectives.objectives()[k]), c->record.trans_mean_m));
      }
    }
    PlotOptions o = options.panel.Plot();
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
