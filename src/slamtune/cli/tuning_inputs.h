// Inputs shared by `slamtune optimize` and `slamtune sweep`: the log (a CARMEN file or a ROS
// recording, or a
// built-in world simulated in memory when none is given), relations, and the base mapper
// parameters from --preset / --params / --set; and the evaluation context both commands build
// from them, on rank 0 and, under mpirun, on every worker rank (optim/mpi_evaluation.h).
#pragma once

#include <CLI/CLI.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "slamtune/cli/log_input.h"
#include "slamtune/io/laser_log.h"
#include "slamtune/io/relations.h"
#include "slamtune/metrics/relation_match.h"
#include "slamtune/optim/mpi_evaluation.h"
#include "slamtune/optim/slam_evaluation.h"
#include "slamtune/slam/mapper_params.h"
#include "slamtune/slam/ros_node_files.h"

namespace slamtune::cli {

struct TuningInputOptions {
  std::string log;             // empty: simulate `world`
  std::string relations;
  std::string world = "office";
  unsigned world_seed = 1;
  std::string preset;
  std::string params_file;
  std::vector<std::string> sets;
  LogInputOptions input;  // how the log is read (--lenient, --no-return, --beams, bag choices)

  void AddTo(CLI::App& app);
  // Everything that changes results, for the run database and --resume.
  nlohmann::json ToJson() const;
  static TuningInputOptions FromJson(const nlohmann::json& j);
};

struct TuningInputs {
  std::shared_ptr<const io::LaserLog> log;
  std::vector<io::Relation> relations;
  slam::MapperParams base;      // the base configuration every run starts from
  std::string base_label;       // "your configuration (FILE)", "slam_toolbox's defaults", ...
  std::string base_file_text;   // the user's parameter file, "" without --params
  slam::RosNode base_node = slam::RosNode::kSlamKarto;  // the node the base is written for
  std::string log_label;        // path, or "built-in world NAME (seed N)"
  std::string relations_label;  // path, "simulated", or empty
  std::vector<std::string> log_input;  // what was read and chosen (io::DescribeLogInput)
};

// The configuration runs start from: the user's parameter file (`params_file`) over the
// defaults of the node it is written for (slam::NodeOfParamsFile; `preset` instead when given),
// else `preset`'s own defaults (slam_karto when empty); then each `sets` NAME=VALUE. The label
// names it for the report: "your configuration (FILE)" or "<preset>'s defaults".
struct BaseConfiguration {
  slam::MapperParams params;
  std::string label;
  std::string file_text;  // the user's file, "" without one
  slam::RosNode node = slam::RosNode::kSlamKarto;  // the node the base is written for
};
BaseConfiguration LoadBaseConfiguration(const std::string& params_file, const std::string& preset,
                                        const std::vector<std::string>& sets);

// Loads and validates everything; throws InputError naming the file and problem (relations
// that match no scan of the log among them, metrics::RequireMatchingRelations).
TuningInputs LoadTuningInputs(const TuningInputOptions& options, bool quiet);

// "slamtune: warning: FILE: N of M relations match scans of the log; ..." on stderr.
void WarnPartialRelations(const std::string& relations_file, const metrics::RelationMatch& match);

// The work shared by all SLAM runs of one command (optim::ShareWork; --no-share turns it off,
// results are identical either way). InputError for share_mb 0.
void ShareWork(optim::SlamEvaluationContext& context, bool no_share, std::size_t share_mb);

// What every rank evaluates with: the loaded inputs, `fixed` values applied to the base
// parameters, and the work shared between runs (ShareWork).
std::shared_ptr<optim::SlamEvaluationContext> MakeEvaluationContext(const TuningInputs& inputs,
                                                                    const std::map<std::string, double>& fixed,
                                                                    bool no_share, std::size_t share_mb);

// What rank 0 sends the worker ranks (MpiDispatcher::Setup) so that they build the same context.
nlohmann::json WorkerSetup(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                           bool no_share, std::size_t share_mb, bool draw_wall = false);

// A worker rank under mpirun: builds its context from rank 0's WorkerSetup, evaluates what rank
// 0 sends until told to stop, and returns 0.
int ServeAsWorker(const optim::MpiWorld& world);

}  // namespace slamtune::cli
