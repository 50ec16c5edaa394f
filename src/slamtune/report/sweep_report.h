// The outputs of `slamtune sweep LOG --vary g=6:20 --fix r=2`: one parameter varied over a
// range, everything else held, as in the seed paper's Figures 14-15 (Han et al., Sensors
// 2020, §4.4: loop closures and the objectives against the minimum chain size g).
//   sweep.csv   one row per value: loop closures, the three objectives, the second figures,
//               nodes, wall time, ground-truth errors when any point has them, scan indices
//   sweep.png   loop closures and each objective (and the errors) against the value, panels
//   sweep.html  a small self-contained page with the table and the figure
// Points are reported in increasing value (stable for repeated values); failed runs stay in
// the table with their reason and are left out of the figure.
#pragma once

#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/report/figures/optimize_figures.h"

namespace slamtune::report {

struct SweepPoint {
  double value = 0.0;              // the varied parameter's value (ROS units)
  optim::EvaluationRecord record;  // what the run at that value produced
};

struct SweepReportOptions {
  std::string log_path;                // shown in sweep.html; may be empty
  std::vector<std::string> log_input;  // what was read and chosen, "NAME: value" lines
  PanelSize panel{460, 340, 0.45};     // one panel of sweep.png

  void Validate() const;
};

struct SweepReportSummary {
  std::string dir;
  std::vector<std::string> files;  // written, in order
  int points = 0;
  int failed = 0;                  // points whose run failed
  bool with_ground_truth = false;  // any point had errors
};

// Throws InputError (before writing anything) for an empty parameter name, no points or a
// non-finite value, and naming the path when the folder or a file cannot be written.
SweepReportSummary WriteSweepReport(const std::string& parameter, const std::vector<SweepPoint>& points,
                                    const std::string& dir, const SweepReportOptions& options = {});

}  // namespace slamtune::report
