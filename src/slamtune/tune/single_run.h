// `slamtune run` as library work: one SLAM run of a log (or a built-in world) with the base
// configuration, evaluated by the tuner's own pipeline (optim::EvaluateSlam: the same engine,
// map and metrics as every run of an optimisation), and its files: map.pgm + map.yaml as
// map_saver writes them, map.png, trajectory.txt, loop_closures.csv, front_end.csv,
// front_end_map.png and run.json. The output folder is checked before the log is read.
#pragma once

#include <optional>
#include <string>

#include "slamtune/common/progress.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

struct RunOptions {
  TuningInputOptions inputs;     // the log (or world), relations and base configuration
  std::string out;               // output folder (created)
  bool no_loop_closure = false;  // do_loop_closing = false over the base
  std::string trace;             // a file for every match and solve (slam/run_trace.h); "" = none
  bool quiet = false;            // only data loss and warnings on stderr
};

struct RunOutcome {
  optim::SlamRun run;  // the run, its map and metrics
  slam::NodeMode node_mode = slam::NodeMode::kSlamKarto;
  std::optional<metrics::GtError> error;  // with relations
  std::string relations_label;            // the relations' file or origin
};

// Loads the inputs (LoadTuningInputs), runs SLAM with progress every 50 scans on `progress`,
// writes every file to options.out. InputError when no reading lies within the range threshold
// (nothing to map).
RunOutcome RunAndWrite(const RunOptions& options, Progress& progress);

}  // namespace slamtune::tune
