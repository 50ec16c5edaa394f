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

// The parts of `run`'s summary line that depend on the run, each "" when there is nothing to say:
// "; slam_toolbox online_sync_launch.py (synchronous node) kept 120 scans from Karto (100 not
// moved, 16 too soon, 4 warming up)" when the node held scans back from Karto;
std::string NodeRefusalsText(const slam::RunSummary& summary, slam::NodeMode mode);
// "lasers: laser_0 (180 readings) 2412 nodes, laser_1 (179 readings) 1207 nodes (--beams
// per-geometry: ...)" with more than one laser;
std::string LasersText(const slam::LogLasers& lasers, const slam::RunSummary& summary);
// ", error 0.0123 +- 0.0100 m, 0.52 +- 0.40 deg (812 relations)" with relations.
std::string RelationErrorText(const std::optional<metrics::GtError>& error);

}  // namespace slamtune::tune
