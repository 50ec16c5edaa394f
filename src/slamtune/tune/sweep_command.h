// `slamtune sweep` as library work: one parameter swept over a range (--vary NAME=LO:HI[:STEP]),
// the others held (--fix), every value one SLAM run of the tuning inputs, and the sweep's report
// (report/sweep_report.h) — the seed paper's Figures 14-15.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/report/sweep_report.h"
#include "slamtune/tune/optimize/tuning_process.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

// --vary NAME=LO:HI[:STEP], NAME a full ROS name (r, g, p, q are expanded).
struct SweepRange {
  std::string name;
  double lo = 0, hi = 0, step = 1;
};

// InputError naming --vary for a malformed range, reversed bounds, a step <= 0 or more than
// 10000 values.
SweepRange ParseSweepRange(const std::string& vary);

// One assignment per value of `range` (LO, LO + STEP, ... up to HI), each with the --fix
// NAME=VALUE values; every one validated against `context` before any work.
std::vector<optim::Assignment> SweepBatch(const SweepRange& range, const std::vector<std::string>& fix,
                                          const optim::SlamEvaluationContext& context);

struct SweepOptions {
  TuningInputOptions inputs;
  TuningRunOptions run;
  std::string vary;              // NAME=LO:HI[:STEP]
  std::vector<std::string> fix;  // NAME=VALUE
  std::string out;               // output folder (created)
};

struct SweepOutcome {
  std::string name;                        // the swept parameter's ROS name
  std::vector<report::SweepPoint> points;  // by value
  bool with_errors = false;                // relations were given or simulated
  report::SweepReportSummary report;
  optim::BatchEvaluatorStats evaluations;
  std::string shared_work;  // the shared caches' statistics (optim::SharedWorkReport)
};

// One finished run of a sweep, for progress.
struct SweepStep {
  const std::string& name;  // the swept parameter
  double value;             // its value in this run
  int loop_closures;        // the run's
  std::size_t done, total;  // runs evaluated, and of how many
};

// Called with the headline before the first run, and after each run.
struct SweepHooks {
  std::function<void(const std::string& headline)> started;
  std::function<void(const SweepStep& step)> evaluated;
};

// Checks everything, runs the sweep (on the worker ranks too under mpirun) and writes its report.
SweepOutcome RunSweep(const SweepOptions& options, TuningProcess& process, const SweepHooks& hooks);

}  // namespace slamtune::tune
