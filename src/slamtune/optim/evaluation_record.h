// What one evaluation of a parameter set produced: the map figures the objectives are read
// from (objective_set.h: the seed paper's eta, corner pixels and enclosed areas, and the
// unbacked-hit share), the SLAM run's outcome, and ground-truth errors when relations were
// given. Stored one row per evaluation in the run's SQLite database, so it converts to and from
// JSON.
//
// The figures are listed once, in RecordFigures(): their keys, how each is read off a record and,
// for those an objective set may minimise, the objective's names and failure score. The record's
// JSON, evaluations.csv, sweep.csv, the objective sets and the report iterate that table, so a new
// figure or objective is one row there and, when it is measured rather than derived, one field of
// EvaluationRecord filled in evaluation/slam_evaluation.cc.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slamtune::optim {

// Whether an evaluation's SLAM run gave a map to score: kFailed when the run threw or its map
// has nothing to score (the reason says which); a failed record scores worst on every objective.
enum class RunStatus { kOk, kFailed };

// "ok", "failed": the text results.json, the CSV tables and the run database hold.
const char* NameOf(RunStatus status);
// The status written as `name`; InputError for any other text.
RunStatus ParseRunStatus(std::string_view name);

struct EvaluationRecord {
  std::string key;                       // SearchSpace::Key of the full assignment
  std::map<std::string, double> params;  // ROS name -> value (varied and fixed)
  RunStatus status = RunStatus::kOk;
  std::string reason;  // why it failed (exception text, NaN, ...)

  // Map figures (metrics/map_quality.h, slam/occupancy_grid.h), each a row of RecordFigures();
  // objective_set.h picks the objectives among them.
  double occupied_ratio = 0.0;         // eta
  double corner_pixels = 0.0;          // n_c (objective)
  double enclosed_areas = 0.0;         // n_e
  double occupied_ratio_known = 0.0;   // occupied / (occupied + free)
  double corners = 0.0;                // 8-connected corner clusters
  double contours = 0.0;               // all contours
  double occupied_cells = 0.0;         // wall cells of the map
  double hits = 0.0;                   // scan end points counted in the map (slam/occupancy_grid.h)
  double hits_in_free_cells = 0.0;     // ... of them in cells the map ends up calling free
  double hits_in_unknown_cells = 0.0;  // ... and in cells it leaves unknown
  // Wall cells of the map the log's fixed scans draw along the run's path
  // (metrics/trajectory_map.h), whatever the node spacing; 0 when the evaluation drew none.
  double drawn_wall_cells = 0.0;

  int nodes = 0;
  int loop_closures = 0;
  std::vector<int> loop_scans;  // log scan index of each accepted loop closure
  double wall_s = 0.0;

  bool has_gt = false;
  double trans_mean_m = 0.0, trans_std_m = 0.0, rot_mean_deg = 0.0, rot_std_deg = 0.0;
  int relations_used = 0;

  // Whether the run gave a map to score (status kOk).
  bool ok() const { return status == RunStatus::kOk; }

  static EvaluationRecord Failed(const std::string& key, const std::map<std::string, double>& params,
                                 const std::string& reason);
};

// One figure a record holds, and, for the figures an objective set may minimise, what makes it an
// objective: its short name, title and the score of a failed run. The one list of figures and
// objectives is RecordFigures(); the record's JSON, evaluations.csv, sweep.csv, the objective
// sets (objective_set.h) and the report's figures iterate it.
struct RecordFigure {
  const char* key;                                   // JSON and CSV name, e.g. "corner_pixels"
  double EvaluationRecord::*field;                   // the record's field; nullptr for a derived figure
  double (*derive)(const EvaluationRecord& record);  // a derived figure's value; nullptr otherwise
  // False for figures added after the first stored records: a record without it reads as 0.
  bool in_every_stored_record;
  // An objective's names and failure score; nullptr / 0 for a figure no objective set minimises.
  const char* short_name;  // in figures and table headers: "eta", "n_c", "n_e", "u_h"
  const char* title;       // in prose: "corner pixels (n_c)"
  double failure_score;    // a failed run's score: worse than any real map

  bool derived() const { return field == nullptr; }
  bool is_objective() const { return short_name != nullptr; }
};

// Every figure, in the column order of evaluations.csv and sweep.csv.
std::span<const RecordFigure> RecordFigures();
// The figure called `key`; a broken invariant (SLAMTUNE_CHECK) for a key not in the table.
const RecordFigure& FigureNamed(std::string_view key);
// The figure's value in `record` (no failure scoring: see ObjectiveSet::Score).
double FigureValue(const RecordFigure& figure, const EvaluationRecord& record);

// The record's JSON keeps its measured figures in one object, "figures" (derived figures are
// computed on reading, not stored). Records stored before held the seed paper's three figures in
// "objectives" and the rest in "second"; from_json reads both layouts, so every stored run folder
// reads back.
void to_json(nlohmann::json& j, const EvaluationRecord& r);
void from_json(const nlohmann::json& j, EvaluationRecord& r);

}  // namespace slamtune::optim
