// Before a front-end search: how much wider the base configuration's sequential search must be
// to hold where its front end broke, found by runs of the log's prefix (docs/search-spaces.md,
// "Informed start"). A break (slam/front_end_evidence.h) is a match that ran out of heading range
// or out of window; a wheel slip the odometry missed needs a wider heading range
// (coarse_search_angle_offset), a jump or a stretch of travel reported wrongly a wider window
// (correlation_search_space_dimension).
//
// For each break of the base run, in log order, the parameter of its kind (both for a match at
// both edges) is tried at values of the search space's lattice on a ladder of 1.5, 2, 2.5, 3, 4
// times the base's value and the space's upper bound, on top of the values kept for the breaks
// before. A try runs the log from its start until `margin_matches` sequential matches past the
// break and holds when no break is seen (slam::BreakWatch) and no match from the break on is
// suspect (at the search's edge, or a collapsed response): a search still too narrow may settle
// on a wrong pose inside its range. The first value that holds is
// kept; the largest that broke becomes the parameter's lower bound in the search (with the base's
// other values no smaller one holds there). When none holds, the upper bound is kept and the
// lower bound is the largest value tried below it.
//
// The kept values form the repaired configuration, one individual of the search's first
// generation; the lower bounds narrow the space. A search therefore starts from a configuration
// that holds at every break the base run showed, and spends no run on ranges that cannot.
// Deterministic; the tries are prefix runs (a fraction of a full run each).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/slam/front_end_evidence.h"

namespace slamtune::optim {

struct FrontEndRepairOptions {
  int margin_matches = 30;  // sequential matches past a break a try must make without a break, >= 1

  void Validate() const;
};

struct FrontEndRepair {
  Assignment repaired;                         // the space's values that held (only those changed)
  std::map<std::string, double> lower_bounds;  // raised lower bounds of the space
  std::vector<std::string> tries;              // one line per break: what broke and what held
  int prefix_runs = 0;                         // tries made
  double wall_s = 0.0;

  bool empty() const { return repaired.empty() && lower_bounds.empty(); }
  // One line for the terminal and the report, e.g. "informed start: at log scan 1201 the heading
  // range 0.52 rad broke and 0.70 held; ..."; "" when nothing was tried.
  std::string Describe() const;
};

// The repair of `context.base` at the breaks of its run (`steps`, `evidence`: the base run's
// sequential matches and their assessment), within `space`.
FrontEndRepair RepairFrontEnd(const SlamEvaluationContext& context, const std::vector<slam::SequentialMatchStep>& steps,
                              const slam::FrontEndEvidence& evidence, const SearchSpace& space,
                              const FrontEndRepairOptions& options = {});

// `space` with the repair's lower bounds (kept on the dimensions' lattices).
SearchSpace WithLowerBounds(SearchSpace space, const std::map<std::string, double>& lower_bounds);

}  // namespace slamtune::optim
