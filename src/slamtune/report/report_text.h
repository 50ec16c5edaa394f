// Names and short texts shared by the report's tables, figures and HTML: the three
// objectives of the seed paper (Han et al., Sensors 2020, §3: eta = occupied ratio, n_c =
// corner pixels, n_e = enclosed areas), the order in which candidates are listed (the
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

struct ObjectiveName {
  const char* key;    // JSON/CSV name, as in EvaluationRecord's JSON
  const char* short_name;  // in figures: "eta", "n_c", "n_e"
  const char* title;  // in prose
};
inline constexpr std::array<ObjectiveName, 3> kObjectives = {{
    {"occupied_ratio", "eta", "occupied ratio (eta)"},
    {"corner_pixels", "n_c", "corner pixels (n_c)"},
    {"enclosed_areas", "n_e", "enclosed areas (n_e)"},
}};

// The objective values of a record in kObjectives order (the record's own fields, not the
// failure-scored Objectives()).
std::array<double, 3> ObjectiveValues(const optim::EvaluationRecord& record);

// True for an objective vector that is the failure score of EvaluationRecord::Objectives()
// (n_c or n_e >= 1e9), has the wrong length, or holds a non-finite value: such points are
// left out of the figures, where they would squash every real point into a corner.
bool IsFailureScore(const std::vector<double>& objectives);

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
