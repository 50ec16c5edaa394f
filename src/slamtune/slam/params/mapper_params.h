// Every parameter of the Karto mapper under its ROS name, in ROS units (docs/engine.md §9).
//
// MapperParams is what a slam_karto / slam_toolbox user writes in a YAML file: the values keep
// ROS units, so the three squared parameters (loop_match_maximum_variance_coarse,
// distance_variance_penalty, angle_variance_penalty, §9.1 note ²) are stored as given and
// squared only where the engine uses them (the *Internal() accessors). Defaults are
// slam_karto's config/mapper_params.yaml (§9.1 "slam_karto YAML" column) plus the laser and
// map items of §9.2; presets switch to open_karto's internal defaults or slam_toolbox's YAML.
//
// The optimiser tunes any numeric parameter by name: ParamTable() lists every parameter with
// its type and rule, GetNumeric / SetNumeric read and write it, Validate() names the
// parameter, the value and the allowed range in its InputError.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "slamtune/slam/backend/pose_graph_solver.h"
#include "slamtune/slam/matching/scan_matcher.h"
#include "slamtune/slam/occupancy_grid.h"

namespace slamtune::slam {

// Which node's rule sets the laser range threshold (§9.2), named after the node.
enum class RangeThresholdRule { kSlamKarto, kSlamToolbox };
// "slam_karto" or "slam_toolbox", as parameter files name it.
const char* NameOf(RangeThresholdRule rule);

// Which ROS node, started how, hands the recording's scans to Karto (docs/engine.md §3.4,
// docs/ros-nodes.md "Node modes"); node_scan_filter.h applies its rule:
//   kSlamKarto          slam_karto: every throttle_scans-th message;
//   kSlamToolboxAsync   slam_toolbox's online_async_launch.py: every scan (throttle_scans unused);
//   kSlamToolboxSync    online_sync_launch.py: the synchronous node's shouldProcessScan filter;
//   kSlamToolboxOffline offline_launch.py: the same synchronous node and filter, started with
//                       mapper_params_offline.yaml (whose mapper values are the same).
enum class NodeMode { kSlamKarto, kSlamToolboxAsync, kSlamToolboxSync, kSlamToolboxOffline };
// "slam_karto", "slam_toolbox_async", "slam_toolbox_sync", "slam_toolbox_offline".
const char* NameOf(NodeMode mode);
// Whether the mode is slam_toolbox's synchronous node, which filters scans before Karto.
bool IsSynchronous(NodeMode mode);
// The mode's launch file and parameter file, for comments and the report, e.g.
// "slam_toolbox online_sync_launch.py (synchronous node)".
const char* LaunchOf(NodeMode mode);

// Texts read for choice parameters that name none of their choices, by parameter name. A reader
// that assigns many values keeps them here instead of stopping at the first, so that
// Validate(unknown_choices) reports every value out of range in one order, the table's.
using UnknownChoices = std::map<std::string, std::string, std::less<>>;

struct MapperParams {
  // --- Mapper parameters of §9.1 (ROS names, ROS units; slam_karto YAML defaults) ---
  bool use_scan_matching = true;                    // false: no graph, poses are pure odometry (§3.2)
  bool use_scan_barycenter = true;                  // distance tests between barycentres, not sensor poses (§2.2)
  double minimum_time_interval = 3600;              // s; a scan this much newer than the last accepted one passes
  double minimum_travel_distance = 0.2;             // m; odometric sensor travel that accepts a scan (§3.2 step 5)
  double minimum_travel_heading = 0.174;            // rad; odometric sensor turn that accepts a scan
  int scan_buffer_size = 70;                        // scans kept in the running buffer (§3.3)
  double scan_buffer_maximum_scan_distance = 20.0;  // m; front-to-back span of the running buffer
  double link_match_minimum_response_fine = 0.8;    // near-chain link accepted if response > this - 1e-6
  double link_scan_maximum_distance = 10.0;         // m; L: near chains and LinkChainToScan radius (§5.2)
  double loop_search_maximum_distance = 4.0;        // m; r: loop candidate radius between barycentres (§6.2)
  bool do_loop_closing = true;
  int loop_match_minimum_chain_size = 10;                  // g: min run length of a loop candidate / near chain
  double loop_match_maximum_variance_coarse = 0.4;         // m (ROS); q, squared to q^2 m^2 inside (§6.3)
  double loop_match_minimum_response_coarse = 0.8;         // p: coarse loop response must be > p (§6.3)
  double loop_match_minimum_response_fine = 0.8;           // fine loop response must be >= this (§6.4)
  double correlation_search_space_dimension = 0.3;         // m; sequential matcher window D
  double correlation_search_space_resolution = 0.01;       // m; sequential matcher rho
  double correlation_search_space_smear_deviation = 0.03;  // m; sequential matcher sigma
  double loop_search_space_dimension = 8.0;                // m; loop matcher window
  double loop_search_space_resolution = 0.05;              // m; loop matcher rho
  double loop_search_space_smear_deviation = 0.03;         // m; loop matcher sigma
  double distance_variance_penalty = 0.3;                  // m (ROS); squared inside (§4.5)
  double angle_variance_penalty = 0.349;                   // rad (ROS); squared inside
  double fine_search_angle_offset = 0.00349;               // rad; really the fine angular step (§4.2 item 6)
  double coarse_search_angle_offset = 0.349;               // rad; +- coarse angular range
  double coarse_angle_resolution = 0.0349;                 // rad; coarse angular step
  double minimum_angle_penalty = 0.9;                      // floor of the angular penalty factor
  double minimum_distance_penalty = 0.5;                   // floor of the distance penalty factor
  bool use_response_expansion = false;                     // widen the coarse angle search on a zero response
  // The pose graph's frame. false (slam_karto, open_karto): edges between sensor poses and
  // solved values written back as sensor poses (new nodes start at the robot pose, §7.3).
  // true (slam_toolbox): edges between robot (base) poses, the match covariances unchanged,
  // values written back as robot poses. The same when the laser sits at the base origin.
  bool robot_pose_graph = false;

  // --- Laser and map items of §9.2 ---
  // slam_karto: rangeThreshold = clip(12, min_range, maxRange). slam_toolbox:
  // clip(min(max_laser_range, maxRange), ...), with max_laser_range <= 0 meaning maxRange.
  RangeThresholdRule range_threshold_rule = RangeThresholdRule::kSlamKarto;
  double max_laser_range = 20.0;      // m; slam_toolbox's rangeThreshold (only for that rule)
  double min_laser_range = 0.0;       // m; minRange (LaserScan range_min; CARMEN logs have none)
  double laser_max_range_cap = 80.0;  // m; maxRange = min(this, the log's no-return value) (§2.3)
  double resolution = 0.05;           // m per map cell
  int min_pass_through = 2;           // a cell needs more passes than this to be known (§8.1)
  double occupancy_threshold = 0.1;   // hit/pass above this is occupied (§8.1)
  // --- The node around Karto (§3.4) ---
  NodeMode node_mode = NodeMode::kSlamKarto;  // which node feeds Karto, and how
  int throttle_scans = 1;                     // slam_karto and the synchronous node: every n-th scan
  // s; the synchronous node's own minimum_time_interval (slam_toolbox files' key of that name,
  // whose undeclared default is transform_timeout's value); the asynchronous node ignores it.
  double sync_minimum_time_interval = 0.5;

  // --- Back-end (§7) ---
  SolverKind solver = SolverKind::kSpa;              // kSpa (slam_karto, SPA LM) or kCeres (slam_toolbox)
  CeresLoss ceres_loss_function = CeresLoss::kNone;  // scale 0.7
  CeresLinearSolver ceres_linear_solver = CeresLinearSolver::kSparseNormalCholesky;
  CeresPreconditioner ceres_preconditioner = CeresPreconditioner::kJacobi;  // unused by sparse Cholesky
  CeresTrustStrategy ceres_trust_strategy = CeresTrustStrategy::kLevenbergMarquardt;
  CeresDoglegType ceres_dogleg_type = CeresDoglegType::kTraditional;  // with DOGLEG only
  // The ceres_* choices together, for MakeSolver.
  CeresChoices Ceres() const {
    return {ceres_loss_function, ceres_linear_solver, ceres_preconditioner, ceres_trust_strategy, ceres_dogleg_type};
  }

  // --- Engine only ---
  int matcher_threads = 1;  // threads of the correlative search; results do not depend on it

  // Internal (squared) values used by the engine (§9.1 note ²).
  double LoopMatchMaximumVarianceCoarseInternal() const {
    return loop_match_maximum_variance_coarse * loop_match_maximum_variance_coarse;
  }
  double DistanceVariancePenaltyInternal() const { return distance_variance_penalty * distance_variance_penalty; }
  double AngleVariancePenaltyInternal() const { return angle_variance_penalty * angle_variance_penalty; }

  // Options of the sequential (CorrelationSearchSpace*) and loop (LoopSearchSpace*) matchers
  // for a laser with this range threshold (§3.1, §4.1).
  ScanMatcherOptions SequentialMatcherOptions(double range_threshold) const;
  ScanMatcherOptions LoopMatcherOptions(double range_threshold) const;

  // Range threshold of §9.2 for a laser with these limits (m).
  double RangeThreshold(double min_range, double max_range) const;

  // Throws InputError "NAME = VALUE is out of range: RULE" for the first violated rule.
  void Validate() const;
  // Validate(), with texts a reader found for choice parameters that name none of their
  // choices reported as out of range where their parameter comes (UnknownChoices).
  void Validate(const UnknownChoices& unknown_choices) const;

  // Presets (PresetNames()): "slam_karto" (the defaults above), "open_karto" (Karto's internal
  // defaults, in ROS units), "slam_toolbox" (the asynchronous node with its shipped
  // mapper_params_online_async.yaml, Ceres back-end), "slam_toolbox_sync" and
  // "slam_toolbox_offline" (the synchronous node with mapper_params_online_sync.yaml /
  // mapper_params_offline.yaml, whose mapper values are the asynchronous file's). Throws
  // InputError for other names.
  static MapperParams Preset(std::string_view name);

  friend bool operator==(const MapperParams&, const MapperParams&) = default;
};

// The presets' names, in the order help texts list them.
const std::vector<std::string>& PresetNames();
// "slam_karto, open_karto, slam_toolbox, slam_toolbox_sync or slam_toolbox_offline".
std::string PresetList();

// Options of the occupancy grid these parameters draw (§8.1, §9.2): resolution, min_pass_through
// and occupancy_threshold; max_cells keeps its default.
OccupancyGridOptions GridOptionsOf(const MapperParams& params);

enum class ParamType { kBool, kInt, kDouble, kString };

const char* ParamTypeName(ParamType type);

// One row of the parameter table.
struct ParamInfo {
  const char* name;  // ROS name
  ParamType type;
  bool ros;             // a real slam_karto / slam_toolbox ROS parameter (written to ROS YAML)
  const char* rule;     // allowed values, for messages and --help
  const char* meaning;  // one line, with unit
};

// All parameters, in declaration order.
const std::vector<ParamInfo>& ParamTable();
// nullptr when unknown.
const ParamInfo* FindParam(std::string_view name);
// "unknown mapper parameter 'NAME'", with the closest known name when it looks like a typo.
std::string UnknownParamMessage(std::string_view name);

// Choice parameters (range_threshold_rule, node_mode, solver, ceres_*) read and write as text:
// the name of their value, as parameter files have it.
using ParamValue = std::variant<bool, int, double, std::string>;

struct NamedParam {
  std::string name;
  ParamValue value;
};

// Name -> value in table order (for run.json and the ROS YAML).
std::vector<NamedParam> ToNamedValues(const MapperParams& params);

// Numeric access by ROS name for the optimiser: bools read as 0/1, ints as integers.
// Unknown or string parameters throw InputError.
double GetNumeric(const MapperParams& params, std::string_view name);
// Sets a numeric parameter and validates the result; on error `params` is unchanged.
// Ints must be integral, bools 0 or 1.
void SetNumeric(MapperParams& params, std::string_view name, double value);
// Sets several and validates once, after all: a consistent set (e.g. a matcher's dimension,
// resolution and smear changed together) is taken whatever the order.
void SetNumerics(MapperParams& params, const std::map<std::string, double>& values);
// SetNumeric / SetFromString without validating the whole set: for readers that assign many
// values and call Validate() after the last. Type and format are still checked; a text that
// names no choice of a choice parameter goes to `unknown_choices`, or without one throws the
// InputError Validate() gives for a value out of range.
void AssignNumeric(MapperParams& params, std::string_view name, double value);
void AssignFromString(MapperParams& params, std::string_view name, std::string_view text,
                      UnknownChoices* unknown_choices = nullptr);
// Sets any parameter from text ("true"/"false"/"1"/"0" for bools); validates; on error
// `params` is unchanged.
void SetFromString(MapperParams& params, std::string_view name, std::string_view text);
// "name=value" override, as given to --set.
void ApplyOverride(MapperParams& params, std::string_view assignment);
// Several overrides, validated together after the last (see SetNumerics).
void ApplyOverrides(MapperParams& params, const std::vector<std::string>& assignments);

}  // namespace slamtune::slam
