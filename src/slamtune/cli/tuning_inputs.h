// What `slamtune optimize` and `slamtune sweep` share: the inputs (the log, a CARMEN file or a
// ROS recording, or a built-in world simulated in memory when none is given; relations; the
// base mapper parameters from --preset / --params / --set), how the SLAM runs are carried out
// (--jobs, --quiet, --no-share, --share-mb), the evaluation context built from them, and the
// process's part in an MPI job: rank 0 drives and writes, every other rank builds the same
// context and only evaluates (optim/mpi_evaluation.h). Each option is defined and checked
// here once, so the two commands take and describe them alike.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/cli/log_input.h"
#include "slamtune/io/laser_log.h"
#include "slamtune/io/relations.h"
#include "slamtune/io/scan_losses.h"
#include "slamtune/metrics/relation_match.h"
#include "slamtune/optim/batch_evaluator.h"
#include "slamtune/optim/mpi_evaluation.h"
#include "slamtune/optim/slam_evaluation.h"
#include "slamtune/slam/base_configuration.h"
#include "slamtune/slam/mapper_params.h"
#include "slamtune/slam/ros_node_files.h"

namespace slamtune::cli {

struct TuningInputOptions {
  std::string log;  // empty: simulate `world`
  std::string relations;
  std::string world = "office";
  unsigned world_seed = 1;
  std::string preset;
  std::string params_file;
  std::vector<std::string> sets;
  // How --params and --preset combine (slam/base_configuration.h); folders written before the
  // rule resume with the old one.
  slam::BaseRule base_rule = slam::BaseRule::kNodeDefaults;
  LogInputOptions input;  // how the log is read (--lenient, --no-return, --beams, bag choices)

  void AddTo(CLI::App& app);
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
  std::string log_label;                                // path, or "built-in world NAME (seed N)"
  std::string relations_label;                          // path, "simulated", or empty
  std::vector<std::string> log_input;                   // what was read and chosen (io::DescribeLogInput)
  io::ScanLosses scans_not_used;  // the log's scans no run maps (io::ReadingLosses for the base's node)
};

// The --preset option of every command that starts from a base configuration
// (slam/base_configuration.h), with one help text.
CLI::Option* AddPresetOption(CLI::App& app, std::string& preset);
// "slamtune: warning: ..." on stderr for each warning of the parameter file's reading (values the
// node reads otherwise than written, keys whose effect is not modelled).
void PrintParamsWarnings(const slam::BaseConfiguration& base);

// What LoadTuningInputs says on stderr: everything read and chosen; only the data of the
// recording that is not used (--quiet: quiet silences progress, not data loss); nothing (a
// worker rank, whose rank 0 says it).
enum class InputNotes { kAll, kDataLoss, kNone };
// Loads and validates everything; throws InputError naming the file and problem (relations
// that match no scan of the log among them, metrics::RequireMatchingRelations).
TuningInputs LoadTuningInputs(const TuningInputOptions& options, InputNotes notes);

// "slamtune: warning: FILE: N of M relations match scans of the log; ..." on stderr.
void WarnPartialRelations(const std::string& relations_file, const metrics::RelationMatch& match);

// How a tuning command carries out its SLAM runs: how many at once, whether they share work
// (results are identical either way) and whether progress is shown. None of it changes
// results, so all of it may accompany `optimize --resume`.
struct TuningRunOptions {
  int jobs = DefaultJobs();
  bool quiet = false;
  bool no_share = false;       // evaluate without the shared caches
  std::size_t share_mb = 512;  // MB, memory budget of the shared scan-match cache

  // Adds --jobs/-j and --quiet/-q; returns them.
  std::vector<CLI::Option*> AddParallelismTo(CLI::App& app);
  // Adds --no-share and --share-mb; returns them.
  std::vector<CLI::Option*> AddSharingTo(CLI::App& app);
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

// What rank 0 sends the worker ranks (MpiDispatcher::Setup) so that they build the same context.
// `stop_broken_runs`: SlamEvaluationContext::stop_broken_runs.
nlohmann::json WorkerSetup(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                           const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs = false);

// Creates the output folder `dir` (and its parents); InputError "DIR: cannot create output
// folder: REASON".
void CreateOutputFolder(const std::string& dir);
// CreateOutputFolder, then checks that a file can be written in it (InputError "DIR: output
// folder is not writable").
void EnsureWritableOutputFolder(const std::string& dir);

// A worker rank under mpirun: builds its context from rank 0's WorkerSetup, evaluates what rank
// 0 sends until told to stop, and returns 0.
int ServeAsWorker(const optim::MpiWorld& world);

// This process's part in a tuning command. Started by mpirun with several ranks, rank 0 drives
// the command and hands SLAM runs to the others (the workers), which wait for its WorkerSetup
// and only evaluate (Serve); an error on rank 0 before StopWorkers stops them too. Alone, the
// process does everything and there are no workers.
class TuningProcess {
 public:
  TuningProcess();
  TuningProcess(const TuningProcess&) = delete;
  TuningProcess& operator=(const TuningProcess&) = delete;

  // Whether this is a worker rank, which should only Serve.
  bool is_worker() const { return world_.rank() > 0; }
  // A worker rank's whole life (ServeAsWorker); returns its exit code.
  int Serve() const { return ServeAsWorker(world_); }
  bool has_workers() const { return workers_.has_value(); }
  int ranks() const { return world_.size(); }

  // One rank per core: with workers, rank 0 evaluates on one thread unless `app` was given --jobs.
  void FitJobs(const CLI::App& app, TuningRunOptions& run) const;
  // Sends the workers what they build their context from (WorkerSetup); nothing without workers.
  void SetupWorkers(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                    const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs = false);
  // Lets `evaluator` hand runs to the workers beside its own threads.
  void ShareWith(optim::BatchEvaluator& evaluator);
  // Tells the workers to exit; idempotent.
  void StopWorkers();

  // "K MPI ranks (J evaluating on rank 0)" with workers, else "J jobs".
  std::string Parallelism(int jobs) const;
  // "N of the SLAM runs ran on the K worker ranks" on stdout; nothing without workers.
  void PrintWorkersShare(const optim::BatchEvaluator& evaluator) const;

 private:
  optim::MpiWorld world_;
  std::optional<optim::MpiDispatcher> workers_;
};

}  // namespace slamtune::cli
