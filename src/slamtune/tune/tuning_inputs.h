// What the tuning commands (optimize, sweep, run) share: their inputs (the log, a CARMEN file
// or a ROS recording, or a built-in world simulated in memory when none is given; relations;
// the base mapper parameters from --preset / --params / --set), how the SLAM runs are carried
// out (--jobs, --quiet, --no-share, --share-mb), and the evaluation context built from them.
// Each option is defined and checked here once (its flag: cli/input_flags.h), so the commands
// take and describe them alike, and one loader reads them for every command.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/relations.h"
#include "slamtune/metrics/relation_match.h"
#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/params/base_configuration.h"
#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/params/ros_node_files.h"
#include "slamtune/tune/log_input.h"

namespace slamtune::tune {

struct TuningInputOptions {
  std::string log;  // empty: simulate `world`
  std::string relations;
  std::string world = sim::kDefaultWorld;  // simulated when no log is given
  unsigned world_seed = 1;
  std::string preset;
  std::string params_file;
  std::vector<std::string> sets;
  // How --params and --preset combine (slam/params/base_configuration.h); folders written before the
  // rule resume with the old one (MigrateInvocation, tune/optimize/optimize_options.h).
  slam::BaseRule base_rule = slam::BaseRule::kNodeDefaults;
  LogInputOptions input;  // how the log is read (--lenient, --no-return, --beams, bag choices)

  // Everything that changes results, for the run database and --resume.
  nlohmann::json ToJson() const;
  static TuningInputOptions FromJson(const nlohmann::json& j);
};

struct TuningInputs {
  std::shared_ptr<const io::LaserLog> log;
  std::vector<io::Relation> relations;
  slam::MapperParams base;                              // the base configuration every run starts from
  std::string base_label;                               // "your configuration (FILE)", "slam_toolbox's defaults", ...
  std::string base_file_text;                           // the user's parameter file, "" without --params
  slam::RosNode base_node = slam::RosNode::kSlamKarto;  // the node the base is written for
  // The log's and relations' labels, what was read, and the scans no run maps (io::ReadingLosses
  // for the base's node).
  optim::LogSource source;
};

// "slamtune: warning: ..." on stderr for each warning of the parameter file's reading (values the
// node reads otherwise than written, keys whose effect is not modelled).
void PrintParamsWarnings(const slam::BaseConfiguration& base);

// What LoadTuningInputs says on stderr: everything read and chosen; only the data of the
// recording that is not used (--quiet: quiet silences progress, not data loss); nothing (a
// worker rank, whose rank 0 says it).
enum class InputNotes { kAll, kDataLoss, kNone };
// Loads and validates everything, the same way for every command: the base configuration
// (slam::LoadBaseConfiguration), the relations file, then the log (or the simulated world, whose
// relations stand in for missing --relations), then the relations against the log
// (metrics::RequireMatchingRelations). `before_log` (may be empty) runs once everything but the
// log is checked, before the log is read, e.g. to check the output folder before a long read.
// Throws InputError naming the file and problem.
TuningInputs LoadTuningInputs(const TuningInputOptions& options, InputNotes notes,
                              const std::function<void()>& before_log = {});

// The built-in world `options` names (--world, --world-seed).
sim::SimulationOptions WorldOptions(const TuningInputOptions& options);

// "slamtune: warning: FILE: N of M relations match scans of the log; ..." on stderr.
void WarnPartialRelations(const std::string& relations_file, const metrics::RelationMatch& match);

// How a tuning command carries out its SLAM runs: how many at once, whether they share work
// (results are identical either way) and whether progress is shown. None of it changes
// results, so all of it may accompany `optimize --resume`.
struct TuningRunOptions {
  int jobs = DefaultJobs();
  bool quiet = false;
  bool no_share = false;       // evaluate without the shared caches
  std::size_t share_mb = 512;  // MB, memory budget of the shared scan-match cache (solves get half more)

  // Throws InputError for --jobs < 1.
  void Validate() const;

  // One SLAM run per core.
  static int DefaultJobs();
};

// The work shared by all SLAM runs of one command (optim::ShareWork; none with --no-share).
// InputError for share_mb 0.
void ShareWork(optim::SlamEvaluationContext& context, const TuningRunOptions& run);

// What every rank evaluates with: the loaded inputs, `fixed` values applied to the base
// parameters, and the work shared between runs (ShareWork).
std::shared_ptr<optim::SlamEvaluationContext> MakeEvaluationContext(const TuningInputs& inputs,
                                                                    const std::map<std::string, double>& fixed,
                                                                    const TuningRunOptions& run);

// The SLAM runs of `context`, evaluated by a BatchEvaluator.
optim::EvaluateFn EvaluateWith(std::shared_ptr<const optim::SlamEvaluationContext> context);

// Creates the output folder `dir` (and its parents); InputError "DIR: cannot create output
// folder: REASON".
void CreateOutputFolder(const std::string& dir);
// CreateOutputFolder, then checks that a file can be written in it (InputError "DIR: output
// folder is not writable").
void EnsureWritableOutputFolder(const std::string& dir);

}  // namespace slamtune::tune
