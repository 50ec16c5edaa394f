// Do the ground-truth-free objectives track the true error on this log? With relations
// (Kümmerle et al. 2009) every evaluation also has a translational error; the report ranks
// the distinct parameter sets by each objective and by that error and gives Spearman's rho
// (rank_correlation.h): a rank statistic, because the objectives are only meant to order runs
// (NSGA-III uses nothing but their order), not to be proportional to the error.
//
// The objectives are minimised and so is the error: a positive rho means "lower objective,
// lower error", i.e. the objective tracks the error.
#pragma once

#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/report/rank_correlation.h"

namespace slamtune::report {

struct CorrelationReadingOptions {
  double strong = 0.5;  // rho at or above this: "tracks"; in (weak, 1]
  double weak = 0.2;    // rho at or above this: "weakly tracks"; |rho| below: "does not track"; in (0, 1)
  int min_sets = 5;     // fewer distinct parameter sets: "too few to judge"; >= 3

  void Validate() const;
};

// How one objective relates to the error, by the thresholds of CorrelationReadingOptions.
enum class Tracking { kTracks, kWeakly, kNot, kAgainst, kUndecided };

struct ObjectiveErrorCorrelation {
  std::string objective;     // the objective's key in RecordFigures(), e.g. "unbacked_hits"
  std::string short_name;    // its short name, e.g. "u_h"
  RankCorrelation spearman;  // objective vs translational mean error
  Tracking tracking = Tracking::kUndecided;
  std::string reading;  // one sentence in plain words
};

struct ErrorCorrelationSummary {
  int parameter_sets = 0;                             // distinct parameter sets that ran and have ground truth
  std::vector<ObjectiveErrorCorrelation> objectives;  // in the order asked for
  std::string statement;  // a paragraph for the report: the evidence, grouped, and its caveat
};

// The distinct parameter sets (by key; the first evaluation of each) whose run succeeded and
// has ground-truth errors, in evaluation order.
std::vector<optim::EvaluationRecord> GroundTruthRuns(const std::vector<optim::EvaluationRecord>& evaluations);

// Each of `objectives` against the translational error of GroundTruthRuns(evaluations).
ErrorCorrelationSummary CorrelateObjectivesWithError(const std::vector<optim::EvaluationRecord>& evaluations,
                                                     const std::vector<optim::Objective>& objectives,
                                                     const CorrelationReadingOptions& options = {});

}  // namespace slamtune::report
