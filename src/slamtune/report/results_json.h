// results.json of `slamtune optimize`: the machine-readable summary a script or a later
// report reads. Stable top-level keys:
//   recommended, knee, worst, default  each {label, description, params (ROS name -> value),
//       status, reason, objectives {occupied_ratio, corner_pixels, enclosed_areas},
//       second {occupied_ratio_known, corners, contours}, nodes, loop_closures, loop_scans,
//       wall_s, and gt_error {trans_mean_m, trans_std_m, rot_mean_deg, rot_std_deg,
//       relations_used} when the record has ground truth}; null when the run has no such candidate
//   evaluations (SLAM runs done), cache_hits, wall_s, verdict, recommended_share,
//   lowest_error (a label or null), settings, search_space {dimensions [{name, lower, upper,
//   type}], fixed}, log, relations (path or null), and with ground truth
//   error_correlation {parameter_sets, <objective> {rho (null when undefined), n, reading}}.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "slamtune/optim/optimize_result.h"
#include "slamtune/report/error_correlation.h"

namespace slamtune::report {

nlohmann::json CandidateJson(const optim::Candidate& candidate);
nlohmann::json SearchSpaceJson(const optim::SearchSpace& space);

// `correlation`: the objective-vs-error summary, when the run had ground truth.
nlohmann::json ResultsJson(const optim::OptimizeResult& result,
                           const std::optional<ErrorCorrelationSummary>& correlation);

}  // namespace slamtune::report
