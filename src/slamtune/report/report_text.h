// Names and short texts shared by the report's tables, figures and HTML: the objectives of
// a result (optim/objective_set.h), the order in which candidates are listed (the
// paper's Tables 3-10 give the best before the worst; the defaults sit in between), and
// compact renderings of parameter sets.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/optim/search_space.h"

namespace slamtune::report {

// The names of the k-th objective of `result` (k < result.objectives.size()).
const optim::RecordFigure& ObjectiveAt(const optim::OptimizeResult& result, std::size_t k);

// "eta = occupied ratio, n_c = corner pixels, ..." for the objectives of `objectives`.
std::string ObjectiveLegend(const optim::ObjectiveSet& objectives);

// The candidates in report order: recommended, knee, default, worst, then any other label in
// the result's order. Missing labels are skipped.
std::vector<const optim::Candidate*> CandidatesInReportOrder(const optim::OptimizeResult& result);

// Candidates that hold the same parameter set, shown once: label "recommended = knee".
struct CandidateGroup {
  std::string label;                             // the members' labels joined by " = "
  std::vector<const optim::Candidate*> members;  // in report order, at least one
  // The member whose map was rendered (the first one when none was).
  const optim::Candidate& shown() const;
};

// CandidatesInReportOrder merged by parameter set (EvaluationRecord::key, or the parameters
// when a key is empty), in the order of each group's first member.
std::vector<CandidateGroup> MergedCandidates(const optim::OptimizeResult& result);

// The short symbol of a known loop-closure parameter (the paper's r, g, p, q), else the ROS name.
std::string ShortParamName(const std::string& ros_name);

// The unit of a mapper parameter as its table gives it (slam/params/mapper_params.h: "m", "rad"), for
// axis labels; empty for unitless or unknown parameters.
std::string ParamUnit(const std::string& ros_name);

// A number as a reader wants it: at most `significant` significant digits and at most
// `max_decimals` decimals, trailing zeros dropped, "-0" printed as "0", scientific notation
// only below 1e-4 or from 1e9 on; "nan", "inf", "-inf" for the non-finite values. The one
// rounding rule of the report's pages and figures (the CSV files keep %.10g, tables.h), e.g.
// Readable(0.40000000000000002) = "0.4", Readable(1234.5678) = "1235",
// Readable(3.14159, 9, 3) = "3.142" (metres to the millimetre: Metres).
std::string Readable(double value, int significant = 4, int max_decimals = 6);
// A distance in metres to the millimetre ("2.5", "3.142").
std::string Metres(double metres);

// A parameter value for the report: integers without decimals, others Readable (4 significant
// digits, at most 3 decimals: a distance to the millimetre, a response or variance to 1e-3).
std::string FormatParam(double value);

// The parameters ParamSummary shows: the space's varied dimensions that `params` holds, in the
// space's order (all of `params` when the space is empty).
std::vector<std::string> SummarisedParams(const std::map<std::string, double>& params, const optim::SearchSpace& space);
// "r=3.2 g=12" over SummarisedParams.
std::string ParamSummary(const std::map<std::string, double>& params, const optim::SearchSpace& space);

// What ParamSummary's short symbols stand for: "r = loop_search_maximum_distance (m), g = ..." over
// those of `ros_names` that have one (ShortParamName), in order; empty when none has.
std::string ParamLegend(const std::vector<std::string>& ros_names);

// True when any evaluation or candidate carries ground-truth errors, or relations were given.
bool HasGroundTruth(const optim::OptimizeResult& result);

}  // namespace slamtune::report
