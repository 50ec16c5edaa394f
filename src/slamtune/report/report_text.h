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
const optim::ObjectiveInfo& ObjectiveAt(const optim::OptimizeResult& result, std::size_t k);

// "eta = occupied ratio, n_c = corner pixels, ..." for the objectives of `objectives`.
std::string ObjectiveLegend(const optim::ObjectiveSet& objectives);

// The candidates in report order: recommended, knee, default, worst, then any other label in
// the result's order. Missing labels are skipped.
std::vector<const optim::Candidate*> CandidatesInReportOrder(const optim::OptimizeResult& result);

// The short symbol of a known loop-closure parameter (the paper's r, g, p, q), else the ROS name.
std::string ShortParamName(const std::string& ros_name);

// A parameter value: integers without decimals, others with %.10g.
std::string FormatParam(double value);

// "r=3.2 g=12" over the space's varied dimensions (all params when the space is empty).
std::string ParamSummary(const std::map<std::string, double>& params, const optim::SearchSpace& space);

// True when any evaluation or candidate carries ground-truth errors, or relations were given.
bool HasGroundTruth(const optim::OptimizeResult& result);

}  // namespace slamtune::report
