// The CSV tables of `slamtune optimize`, mirroring the seed paper's tables (Han et al.,
// Sensors 2020, §4): Table 3 (best and worst parameters), Tables 4-6 (the objectives with
// their second figures), Table 7 (loop closures), Table 8 (scan indices of the loop
// closures), Tables 9-10 (translational and rotational error against ground-truth
// relations), plus every evaluation of the run.
//
// Candidates are listed recommended, knee, default, worst (report_text.h). A failed run's
// metric cells are left empty (its status says why) rather than showing the zeros of an
// unfilled record; error cells are empty without ground truth.
#pragma once

#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/report/tables.h"

namespace slamtune::report {

// table3_best_worst_params.csv: label, then one column per varied parameter (ROS names).
CsvTable ParamsTable(const optim::OptimizeResult& result);
// table4_6_objectives.csv: label, eta, eta_known, corner_pixels, corners, enclosed_areas, contours.
CsvTable ObjectivesTable(const optim::OptimizeResult& result);
// table7_loop_closures.csv: label, loop_closures.
CsvTable LoopClosuresTable(const optim::OptimizeResult& result);
// table8_loop_scans.csv: label, scan_indices (space-separated log scan indices).
CsvTable LoopScansTable(const optim::OptimizeResult& result);
// table9_10_errors.csv: label, trans_mean_m, trans_std_m, rot_mean_deg, rot_std_deg, relations_used.
CsvTable ErrorsTable(const optim::OptimizeResult& result);

// evaluations.csv: index, every parameter (varied, then fixed, then any other name the
// records carry), status, reason, the objectives and second figures, nodes, loop_closures,
// wall_s and the ground-truth errors.
CsvTable EvaluationsTable(const std::vector<optim::EvaluationRecord>& evaluations, const optim::SearchSpace& space);

// The parameter columns EvaluationsTable uses.
std::vector<std::string> ParameterColumns(const std::vector<optim::EvaluationRecord>& records,
                                          const optim::SearchSpace& space);

// A table cell of one of `record`'s figures: FormatNumber(value), empty for a failed run.
std::string FigureCell(const optim::EvaluationRecord& record, double value);

// "12 57 130" (empty for none).
std::string JoinScans(const std::vector<int>& scans);

}  // namespace slamtune::report
