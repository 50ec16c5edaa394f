// `slamtune optimize` as library work: its inputs loaded, its plan made and its folder locked
// (PrepareOptimization), then the optimisation run, its answer written as parameter files the
// node loads and its report (RunPreparedOptimization). The command line only gathers the
// options and prints what these return.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "slamtune/common/progress.h"
#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/tune/optimize/optimize_options.h"
#include "slamtune/tune/optimize/optimize_plan.h"
#include "slamtune/tune/optimize/recommendation_files.h"
#include "slamtune/tune/optimize/run_folder.h"
#include "slamtune/tune/optimize/tuning_process.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

struct PreparedOptimization {
  TuningInputs inputs;
  OptimizationPlan plan;
};

// Loads and checks every input, plans the optimisation (PlanOptimization), locks the folder,
// records the invocation of a new run and sends the worker ranks their setup. Notes on stderr
// unless run.quiet. InputError before any work for anything wrong.
PreparedOptimization PrepareOptimization(OptimizeOptions& options, const TuningRunOptions& run, RunFolder& folder,
                                         TuningProcess& process);

// What an optimisation produced.
struct OptimizeOutcome {
  optim::OptimizeResult result;
  RecommendationFiles files;               // the parameter files written
  std::size_t report_files = 0;            // report.html, results.json, tables, maps, figures
  optim::BatchEvaluatorStats evaluations;  // how the SLAM runs were carried out
  std::string shared_work;                 // the shared caches' statistics (optim::SharedWorkReport)
};

// Runs the prepared optimisation with progress on `progress` (the shared caches' counts too with
// `verbose`), writes the recommendation's parameter files and the report to the folder. From the
// committed start on, Ctrl-C or a kill says how to resume.
OptimizeOutcome RunPreparedOptimization(PreparedOptimization& prepared, const TuningRunOptions& run, RunFolder& folder,
                                        TuningProcess& process, Progress& progress, bool verbose);

// The first line: what is optimised on what, with which budget and parallelism, and where to.
std::string OptimizeHeadline(const optim::OptimizeSettings& settings, const TuningInputs& inputs,
                             const std::string& parallelism, const std::string& dir);

}  // namespace slamtune::tune
