// The figures of `slamtune optimize`:
// * the candidates' maps side by side (map_panels.h);
// * the population in objective space for one generation, as the three 2D projections of
//   the result's three objectives (e.g. u_h-n_c, u_h-n_e, n_c-n_e) in one 1 x 3 image, with the candidates marked (the
//   seed paper's Figure 13 shows the population moving towards the front over generations);
// * all snapshots overlaid, on the same axes;
// * each objective against the translational error, one panel per objective, with Spearman's
//   rho in the panel title (error_correlation.h);
// * where the search went in parameter space (parameter_space.png). Two searched parameters: a
//   grid of scatter panels of the pair, the same sets coloured once by each objective, once by
//   their loop closures and, with ground truth, once by their true error, so a user sees which
//   region is good by every measure at once. More parameters: parallel coordinates
//   (parallel_coordinates.h), one axis per parameter and one for the first objective, which
//   shows the values the best sets share. One parameter: the first objective against it. The
//   candidates are marked in every view, the default even when it lies outside the search range;
//   failed runs are grey crosses in the scatter panels and counted in the titles elsewhere.
// * the base configuration's front end along the log, and the search's history.
// The population figures share axis limits across generations so they can be compared side by
// side. Failure-scored individuals (ObjectiveSet::IsFailureScore) are left out and counted in
// the figure title. One family a file: optimize_figures.cc (what they share, the maps, objective
// space), parameter_space_figures.cc (with the scatter grid in scatter_grid_figure.cc),
// front_end_figure.cc, history_figure.cc.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/optimize_result.h"
#include "slamtune/report/error_correlation.h"
#include "slamtune/report/figures/map_panels.h"
#include "slamtune/report/figures/parallel_coordinates.h"
#include "slamtune/report/figures/plot.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {

struct FigureOptions {
  PanelSize panel;                     // every plot panel: 520 x 420 px, tick labels at 0.45
  MapPanelOptions maps = LargeMaps();  // the candidates' maps: 640 px high, labels readable at half size

  static MapPanelOptions LargeMaps() {
    MapPanelOptions m;
    m.height = 640;
    m.font_scale = 0.9;
    return m;
  }

  void Validate() const;
};

// Axis limits per objective (the result's objectives order), shared by every population
// figure: from the best value of the non-dominated front of all snapshots' valid individuals
// together (and of the recommended and knee sets) to at most one front range beyond its worst
// value, plus an 8 % margin. Far-off individuals (a broken map scores orders of magnitude
// worse) would otherwise squeeze the front into a corner; the figures count what falls
// outside. nullopt for an objective with no valid value.
std::vector<std::optional<AxisLimits>> ObjectiveLimits(const optim::OptimizeResult& result);

// One map panel per distinct parameter set among the candidates (MergedCandidates): labelled,
// with its loop closures drawn on the map and a scale bar.
struct CandidateMapPanel {
  CandidateGroup group;
  cv::Mat image;
};
std::vector<CandidateMapPanel> CandidateMapPanels(const optim::OptimizeResult& result, const FigureOptions& options);

// The candidates' map panels, two per row, in report order. Requires at least one candidate.
cv::Mat MapsSideBySide(const optim::OptimizeResult& result, const FigureOptions& options);

// One snapshot's population (1 x 3 projections) with the candidates marked.
cv::Mat PopulationFigure(const optim::GenerationSnapshot& snapshot, const optim::OptimizeResult& result,
                         const FigureOptions& options);

// Every snapshot overlaid (1 x 3 projections), one colour and marker per generation.
cv::Mat PopulationEvolutionFigure(const optim::OptimizeResult& result, const FigureOptions& options);

// Each objective against the mean translational error over `runs` (GroundTruthRuns), 1 x 3,
// candidates marked; panel titles carry rho from `correlation`.
cv::Mat ObjectiveVsErrorFigure(const std::vector<optim::EvaluationRecord>& runs,
                               const ErrorCorrelationSummary& correlation, const optim::OptimizeResult& result,
                               const FigureOptions& options);

// What parameter_space.png shows, by the number of searched parameters.
enum class ParameterSpaceView {
  kNone,                 // nothing searched, nothing evaluated or no objective
  kSlices,               // one parameter: the first objective against it (ObjectiveAgainstParameters)
  kScatterGrid,          // two: scatter panels of the pair, one per colouring (ParameterSpacePanels)
  kParallelCoordinates,  // three or more: an axis per parameter and one for the first objective
};
ParameterSpaceView ParameterSpaceViewOf(const optim::OptimizeResult& result);

// What colours the evaluated sets of one scatter panel of the two-parameter grid.
enum class SpaceColouring {
  kObjective,           // the quarter of objective `SpacePanel::objective` among the successful sets
  kLoopClosures,        // the number of loop closures (LoopClosureClasses)
  kTranslationalError,  // the quarter of the mean true translational error among the sets with one
};
struct SpacePanel {
  SpaceColouring colouring = SpaceColouring::kObjective;
  std::size_t objective = 0;  // kObjective: index into the result's objectives
};
// The panels of the grid, in order: one per objective, the loop closures, and the true
// translational error when any successful evaluation has ground truth (has_gt).
std::vector<SpacePanel> ParameterSpacePanels(const optim::OptimizeResult& result);

// A closed range of loop-closure counts shown in one colour.
struct CountClass {
  int lower = 0;
  int upper = 0;
};
// The classes of the loop-closure panel, from the fewest to the most: one per distinct count
// when there are at most `max_classes` (>= 1) of them, else contiguous ranges holding about
// equally many of `counts` each. Empty counts: no classes.
std::vector<CountClass> LoopClosureClasses(std::vector<int> counts, std::size_t max_classes);

// The limits of a parameter's axis in the scatter grid: its search range with a 4 % margin,
// widened to hold the candidates' values `marked` as long as the search range still fills at
// least half of the axis. A value farther out is drawn clamped at the border (PlaceOnAxis) over
// a grey triangle, and the legend says so: a default far outside a narrow range would otherwise
// squeeze the whole search into a corner.
AxisLimits ParameterAxisLimits(const optim::Dimension& dimension, const std::vector<double>& marked);

// The candidates' markers of the scatter grid (two searched parameters, else none), in report
// order (CandidateSeries styles): each at its values of the pair, or, when outside the axes
// (ParameterAxisLimits), just inside the border (PlaceOnAxis) over a large grey triangle (first
// in the list, named once), its legend entry giving the values that lie outside
// ("default (r=30: outside)"). Evaluated sets outside the axes are drawn at the border too.
std::vector<Series> ScatterGridCandidates(const optim::OptimizeResult& result);

// Where the search went: every evaluated parameter set in the search space, with the
// candidates marked (ParameterSpaceView). The scatter grid has one panel per
// ParameterSpacePanels entry (quarters of the objective or error, best quarter green ... worst
// purple; loop-closure counts on a dark-to-light ramp; failed runs grey crosses), three per
// row, and a last panel holding the legend of what every panel shares (candidates, failed
// runs, the search range's outline). Parallel coordinates draw one line per successful set,
// coloured by the quarter of the first objective with the best quarter on top, the recommended
// and default sets thick; each parameter's axis spans its search range and a candidate's value
// beyond it is drawn at the axis's end with a triangle and the value. Empty for kNone.
cv::Mat ParameterSpaceFigure(const optim::OptimizeResult& result, const FigureOptions& options);

// The base configuration's sequential matches along the log (response against seconds into the
// log): every match, those that ended at the search's edge, and the breaks
// (slam/front_end_evidence.h), so a user sees where the map broke.
cv::Mat FrontEndFigure(const optim::BaseFrontEnd& front_end, const FigureOptions& options);

// Slices of the search: objective `k` of every evaluated parameter set against each searched
// parameter (three panels per row, on the population figures' axes for that objective), with
// the candidates marked. ParameterSpaceFigure shows it for the first objective when one parameter
// is searched. Empty when nothing varied, nothing was evaluated or k is out of range.
cv::Mat ObjectiveAgainstParameters(const optim::OptimizeResult& result, std::size_t k, const FigureOptions& options);

// How the search progressed (result.history): one panel per objective with its best value in each
// generation (0 = the initial population), and one with the hypervolume of each generation's
// non-dominated front in objectives normalised over all generations (optim/optimization_history.h),
// on an axis from 0 to its largest possible value, 1.1^objectives. Empty without a history.
cv::Mat HistoryFigure(const optim::OptimizeResult& result, const FigureOptions& options);

// The style of a candidate's marker (by label), shared with the sweep figures.
Series CandidateSeries(const optim::Candidate& candidate, double x, double y);

}  // namespace slamtune::report
