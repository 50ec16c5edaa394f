// Everything `slamtune optimize` leaves for an engineer to read, written into one folder:
//   results.json                  machine-readable summary (results_json.h)
//   table3_best_worst_params.csv, table4_6_objectives.csv, table7_loop_closures.csv,
//   table8_loop_scans.csv and, with ground truth, table9_10_errors.csv
//                                 the seed paper's tables (Han et al., Sensors 2020, §4;
//                                 optimize_tables.h)
//   evaluations.csv               every evaluation of the run
//   maps_side_by_side.png         the candidates' maps (and map_<label>.pgm/.yaml for each
//                                 candidate whose map was rendered)
//   population_gen<k>.png         each snapshot in objective space (1 x 3 projections)
//   population_evolution.png      the snapshots overlaid
//   objective_vs_error.png        with ground truth: each objective against the error
//   report.html                   all of the above on one self-contained page
//
// Every output depends only on the OptimizeResult: writing the same result twice gives
// byte-identical files.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/optimize_result.h"
#include "slamtune/report/error_correlation.h"
#include "slamtune/report/figures/optimize_figures.h"

namespace slamtune::report {

// What was written.
struct OptimizeReportSummary {
  std::string dir;
  std::vector<std::string> files;                      // file names inside dir, in the order written
  int maps_written = 0;                                // candidates whose map went out as PGM + YAML
  std::optional<ErrorCorrelationSummary> correlation;  // with ground truth
};

// Creates `dir` if needed and writes the files above (replacing earlier ones). Throws
// InputError naming the path when the folder cannot be created or a file cannot be written.
OptimizeReportSummary WriteOptimizeReport(const optim::OptimizeResult& result, const std::string& dir,
                                          const FigureOptions& options = {});

}  // namespace slamtune::report
