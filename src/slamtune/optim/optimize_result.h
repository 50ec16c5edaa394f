// Everything `slamtune optimize` found, handed to the report writer (report/): the four
// candidates the report compares (the paper's recommendation, the knee of the final front,
// the worst solution and slam_karto's defaults), every evaluation, and the populations
// in objective space for the figures.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/io/map_image.h"
#include "slamtune/io/scan_losses.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/optim/candidate_selection.h"
#include "slamtune/optim/equivalent_region.h"
#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/optimization_history.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/slam/front_end_evidence.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::optim {

// A loop closure as drawn on a map: the world positions (m, the run's final robot poses) of
// the scan that closed the loop and of the earlier scan its loop edge starts from.
struct LoopEdge {
  double from_x = 0.0, from_y = 0.0;  // the earlier scan (chain member linked to)
  double to_x = 0.0, to_y = 0.0;      // the scan that closed the loop
  int log_index = -1;                 // log scan index of the scan that closed the loop
};

// What re-running one parameter set gives the report: its map and its loop closures on it.
struct CandidateMap {
  io::MapImage map;
  std::vector<LoopEdge> loop_edges;             // one per accepted loop closure
  std::vector<std::pair<double, double>> path;  // robot positions (m) of the processed scans, in order
};

struct Candidate {
  std::string label;        // "recommended", "knee", "worst", "default"
  std::string description;  // one line: how it was chosen
  EvaluationRecord record;
  io::MapImage map;                             // the map of its SLAM run (empty when not rendered)
  std::vector<LoopEdge> loop_edges;             // its loop closures in the map's world frame (empty when not rendered)
  std::vector<std::pair<double, double>> path;  // its robot positions (m), in order (empty when not rendered)
};

struct GenerationSnapshot {
  int generation = 0;                           // 1-based, as in the paper's Figure 13
  std::vector<std::vector<double>> decisions;   // per individual, SearchSpace order
  std::vector<std::vector<double>> objectives;  // per individual, in OptimizeResult::objectives order
};

// What the runs of one command map, as the report and results.json name it: the log (or the
// built-in world) with what was read from it, and the ground truth.
struct LogSource {
  std::string log_label;               // the log's path, or "built-in world NAME (seed N)"
  std::vector<std::string> log_input;  // what was read and chosen (io::DescribeLogInput); empty for a world
  // The log's scans no run maps, by why: the kinds the recording decides (io/scan_losses.h).
  io::ScanLosses scans_not_used;
  std::string relations_label;  // the relations' path, "simulated (true trajectory)", or empty without
};

// The base configuration's run as the front end saw it, when `optimize` chose its space from it.
struct BaseFrontEnd {
  slam::FrontEndEvidence evidence;
  std::vector<slam::SequentialMatchStep> steps;
  std::string choice;          // the line that says which space was searched and why
  std::string informed_start;  // what the prefix runs found the front end needs (front_end_repair.h), or ""
  // The run's map and its poses (one per log scan), to draw the evidence where it happened;
  // an empty map when the run failed before a map was built.
  io::MapImage map;
  std::vector<io::TimedPose> trajectory;
};

struct OptimizeResult {
  LogSource source;
  SearchSpace space;
  ObjectiveSet objectives;  // what was minimised; snapshots' objective vectors follow its order
  nlohmann::json settings;  // population, generations, seed, jobs, ...

  std::vector<Candidate> candidates;  // recommended, knee, worst, default (in that order)
  int recommended_share = 0;          // individuals of the final population with the recommended set
  std::size_t population = 0;         // the final population's size (OptimizeSettings::population); 0: unknown
  // The evaluated sets whose map is equivalent to the recommendation's (equivalent_region.h);
  // absent when the recommendation's run failed.
  std::optional<EquivalentRegion> equivalent_region;
  std::string verdict;  // plain words: is the recommendation better than the base?
  VerdictKind verdict_kind = VerdictKind::kFailed;
  std::string base_label;                                 // the base configuration ("your configuration (FILE)", ...)
  slam::NodeMode node_mode = slam::NodeMode::kSlamKarto;  // the node and mode every run models
  // Set by the command that writes the parameter files, for the report: "name: base -> tuned"
  // (empty when the recommendation is not better) and the commands that load the files.
  std::vector<std::string> changes;
  std::vector<std::string> how_to_load;
  std::string lowest_error_label;              // with relations: the candidate with the lowest translational error
  std::optional<BaseFrontEnd> base_front_end;  // absent when --space was given or the run resumed

  std::vector<EvaluationRecord> evaluations;  // every finished evaluation, in order
  std::vector<GenerationSnapshot> snapshots;  // generations 1, G/2 and G (at least)
  OptimizationHistory history;                // best objectives and hypervolume of every generation (0..G)
  std::size_t evaluation_count = 0;           // SLAM runs done (this process and earlier, resumed)
  unsigned generations_run = 0;               // generations evolved (this process and earlier)
  std::string settling;                       // when and why it stopped (settling.h)
  std::size_t cache_hits = 0;                 // requests served without a SLAM run
  double wall_s = 0.0;

  const Candidate* Find(const std::string& label) const {
    for (const auto& c : candidates)
      if (c.label == label) return &c;
    return nullptr;
  }
};

}  // namespace slamtune::optim
