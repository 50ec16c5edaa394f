#include "slamtune/slam/params/mapper_params.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using Member =
    std::variant<bool MapperParams::*, int MapperParams::*, double MapperParams::*, RangeThresholdRule MapperParams::*,
                 NodeMode MapperParams::*, SolverKind MapperParams::*, CeresLoss MapperParams::*,
                 CeresLinearSolver MapperParams::*, CeresPreconditioner MapperParams::*,
                 CeresTrustStrategy MapperParams::*, CeresDoglegType MapperParams::*>;

// Allowed interval of a numeric parameter; open ends are strict.
struct Bounds {
  double lo = -kInf;
  bool lo_open = false;
  double hi = kInf;
  bool hi_open = false;
};

struct Row {
  ParamInfo info;
  Member member;
  Bounds bounds;
  std::vector<std::string> choices;  // choice parameters only: the names of their values, in enum order
};

Bounds AtLeast(double lo) { return {lo, false, kInf, false}; }
Bounds Above(double lo) { return {lo, true, kInf, false}; }
Bounds Closed(double lo, double hi) { return {lo, false, hi, false}; }
Bounds Any() { return {}; }

// The names of `values`, which must be every value of their enum in order.
template <typename Enum>
std::vector<std::string> ChoiceNames(std::initializer_list<Enum> values) {
  std::vector<std::string> names;
  for (const Enum value : values) {
    SLAMTUNE_CHECK(static_cast<std::size_t>(value) == names.size());
    names.emplace_back(NameOf(value));
  }
  return names;
}

#define ST_BOOL(name, ros, meaning)                                                          \
  Row {                                                                                      \
    {#name, ParamType::kBool, ros, "true or false", meaning}, &MapperParams::name, Any(), {} \
  }
#define ST_NUM(type, name, ros, bounds, rule, meaning)                 \
  Row {                                                                \
    {#name, type, ros, rule, meaning}, &MapperParams::name, bounds, {} \
  }
#define ST_CHOICE(name, ros, rule, meaning, ...) \
  Row { {#name, ParamType::kString, ros, rule, meaning}, &MapperParams::name, Any(), ChoiceNames({__VA_ARGS__}) }

const std::vector<Row>& Rows() {
  using enum ParamType;
  static const std::vector<Row> rows = {
      ST_BOOL(use_scan_matching, true, "match scans and build a graph (false: pure odometry)"),
      ST_BOOL(use_scan_barycenter, true, "measure scan distances between barycentres"),
      ST_NUM(kDouble, minimum_time_interval, true, Any(), "any finite value",
             "s; a scan this much newer than the last accepted one is accepted"),
      ST_NUM(kDouble, minimum_travel_distance, true, AtLeast(0), ">= 0", "m; odometric travel that accepts a scan"),
      ST_NUM(kDouble, minimum_travel_heading, true, AtLeast(0), ">= 0", "rad; odometric turn that accepts a scan"),
      ST_NUM(kInt, scan_buffer_size, true, AtLeast(1), "an integer >= 1", "scans in the running buffer"),
      ST_NUM(kDouble, scan_buffer_maximum_scan_distance, true, AtLeast(0), ">= 0",
             "m; maximum span of the running buffer"),
      ST_NUM(kDouble, link_match_minimum_response_fine, true, Closed(0, 1), "in [0, 1]",
             "minimum response of a near-chain link"),
      ST_NUM(kDouble, link_scan_maximum_distance, true, AtLeast(0), ">= 0",
             "m; radius of near chains and chain-to-scan links"),
      ST_NUM(kDouble, loop_search_maximum_distance, true, AtLeast(0.001),
             ">= 0.001 (smaller radii make a scan its own loop candidate, spec §6.2 item 3)",
             "m; r, loop candidate radius between barycentres"),
      ST_BOOL(do_loop_closing, true, "try to close loops"),
      ST_NUM(kInt, loop_match_minimum_chain_size, true, AtLeast(1), "an integer >= 1",
             "g, minimum length of a loop candidate run and of a near chain"),
      ST_NUM(kDouble, loop_match_maximum_variance_coarse, true, AtLeast(0), ">= 0",
             "m; q, the coarse loop match variances must be < q^2"),
      ST_NUM(kDouble, loop_match_minimum_response_coarse, true, Closed(0, 1), "in [0, 1]",
             "p, the coarse loop response must be > p"),
      ST_NUM(kDouble, loop_match_minimum_response_fine, true, Closed(0, 1), "in [0, 1]",
             "the fine loop response must be >= this"),
      ST_NUM(kDouble, correlation_search_space_dimension, true, Above(0), "> 0", "m; sequential matcher search window"),
      ST_NUM(kDouble, correlation_search_space_resolution, true, Above(0), "> 0",
             "m; sequential matcher grid resolution"),
      ST_NUM(kDouble, correlation_search_space_smear_deviation, true, Above(0), "> 0",
             "m; sequential matcher smearing deviation"),
      ST_NUM(kDouble, loop_search_space_dimension, true, Above(0), "> 0", "m; loop matcher search window"),
      ST_NUM(kDouble, loop_search_space_resolution, true, Above(0), "> 0", "m; loop matcher grid resolution"),
      ST_NUM(kDouble, loop_search_space_smear_deviation, true, Above(0), "> 0", "m; loop matcher smearing deviation"),
      ST_NUM(kDouble, distance_variance_penalty, true, Above(0), "> 0", "m; squared inside; distance penalty"),
      ST_NUM(kDouble, angle_variance_penalty, true, Above(0), "> 0", "rad; squared inside; angle penalty"),
      ST_NUM(kDouble, fine_search_angle_offset, true, Above(0), "> 0", "rad; fine angular step"),
      ST_NUM(kDouble, coarse_search_angle_offset, true, Above(0), "> 0", "rad; coarse angular range (+-)"),
      ST_NUM(kDouble, coarse_angle_resolution, true, Above(0), "> 0", "rad; coarse angular step"),
      ST_NUM(kDouble, minimum_angle_penalty, true, Closed(0, 1), "in [0, 1]", "floor of the angle penalty"),
      ST_NUM(kDouble, minimum_distance_penalty, true, Closed(0, 1), "in [0, 1]", "floor of the distance penalty"),
      ST_BOOL(use_response_expansion, true, "widen the coarse angle search on a zero response"),
      ST_BOOL(robot_pose_graph, false,
              "pose graph over robot (base) poses as slam_toolbox; false: over sensor poses as slam_karto"),
      ST_CHOICE(range_threshold_rule, false, "slam_karto or slam_toolbox",
                "which node's rule sets the laser range threshold", RangeThresholdRule::kSlamKarto,
                RangeThresholdRule::kSlamToolbox),
      ST_NUM(kDouble, max_laser_range, true, Any(), "any finite value (<= 0 means the laser maximum)",
             "m; slam_toolbox's range threshold"),
      ST_NUM(kDouble, min_laser_range, false, AtLeast(0), ">= 0", "m; laser minimum range"),
      ST_NUM(kDouble, laser_max_range_cap, false, Above(0), "> 0",
             "m; laser maximum range = min(this, the log's no-return value)"),
      ST_NUM(kDouble, resolution, true, Above(0), "> 0", "m; map cell size"),
      ST_NUM(kInt, min_pass_through, true, AtLeast(0), "an integer >= 0",
             "a map cell needs more passes than this to be known"),
      ST_NUM(kDouble, occupancy_threshold, true, Closed(0, 1), "in [0, 1]",
             "hit/pass ratio above which a map cell is occupied"),
      ST_CHOICE(node_mode, false, "slam_karto, slam_toolbox_async, slam_toolbox_sync or slam_toolbox_offline",
                "which node feeds Karto, and how (the synchronous node filters scans)", NodeMode::kSlamKarto,
                NodeMode::kSlamToolboxAsync, NodeMode::kSlamToolboxSync, NodeMode::kSlamToolboxOffline),
      ST_NUM(kInt, throttle_scans, true, AtLeast(1), "an integer >= 1",
             "slam_karto and the synchronous node: map every n-th scan"),
      ST_NUM(kDouble, sync_minimum_time_interval, false, AtLeast(0), ">= 0",
             "s; the synchronous node skips scans closer in time to the last one it kept"),
      ST_CHOICE(solver, false, "spa or ceres", "pose-graph back-end (spa = slam_karto, ceres = slam_toolbox)",
                SolverKind::kSpa, SolverKind::kCeres),
      ST_CHOICE(ceres_loss_function, true, "None, HuberLoss or CauchyLoss", "robust loss of the ceres back-end",
                CeresLoss::kNone, CeresLoss::kHuber, CeresLoss::kCauchy),
      ST_CHOICE(ceres_linear_solver, true, "SPARSE_NORMAL_CHOLESKY, SPARSE_SCHUR, ITERATIVE_SCHUR or CGNR",
                "linear solver of the ceres back-end", CeresLinearSolver::kSparseNormalCholesky,
                CeresLinearSolver::kSparseSchur, CeresLinearSolver::kIterativeSchur, CeresLinearSolver::kCgnr),
      ST_CHOICE(ceres_preconditioner, true, "JACOBI, IDENTITY or SCHUR_JACOBI",
                "preconditioner of the ceres back-end's iterative solvers", CeresPreconditioner::kJacobi,
                CeresPreconditioner::kIdentity, CeresPreconditioner::kSchurJacobi),
      ST_CHOICE(ceres_trust_strategy, true, "LEVENBERG_MARQUARDT or DOGLEG",
                "trust-region strategy of the ceres back-end", CeresTrustStrategy::kLevenbergMarquardt,
                CeresTrustStrategy::kDogleg),
      ST_CHOICE(ceres_dogleg_type, true, "TRADITIONAL_DOGLEG or SUBSPACE_DOGLEG",
                "dogleg type of the ceres back-end (with DOGLEG)", CeresDoglegType::kTraditional,
                CeresDoglegType::kSubspace),
      ST_NUM(kInt, matcher_threads, false, AtLeast(1), "an integer >= 1",
             "threads of the correlative search (results do not depend on it)"),
  };
  return rows;
}

#undef ST_BOOL
#undef ST_NUM
#undef ST_CHOICE

const Row* FindRow(std::string_view name) {
  for (const Row& row : Rows()) {
    if (name == row.info.name) return &row;
  }
  return nullptr;
}

std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string UnknownParamMessage(std::string_view name) {
  std::string closest;
  std::size_t best = std::numeric_limits<std::size_t>::max();
  for (const ParamInfo& info : ParamTable()) {
    const std::size_t d = EditDistance(name, info.name);
    if (d < best) {
      best = d;
      closest = info.name;
    }
  }
  // A suggestion only when it is a plausible typo (a few letters off).
  if (best <= std::max<std::size_t>(2, name.size() / 5)) {
    return fmt::format("unknown mapper parameter '{}' (did you mean '{}'?)", name, closest);
  }
  return fmt::format("unknown mapper parameter '{}'", name);
}

namespace {

const Row& RequireRow(std::string_view name) {
  const Row* row = FindRow(name);
  if (row == nullptr) throw InputError(UnknownParamMessage(name));
  return *row;
}

bool InBounds(double v, const Bounds& b) {
  if (!std::isfinite(v)) return false;
  if (b.lo_open ? !(v > b.lo) : !(v >= b.lo)) return false;
  if (b.hi_open ? !(v < b.hi) : !(v <= b.hi)) return false;
  return true;
}

std::string FormatValue(const ParamValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return "'" + v + "'";
        } else {
          return fmt::format("{}", v);
        }
      },
      value);
}

ParamValue ReadValue(const MapperParams& params, const Member& member) {
  return std::visit(
      [&](auto ptr) -> ParamValue {
        if constexpr (std::is_enum_v<std::remove_reference_t<decltype(params.*ptr)>>) {
          return std::string(NameOf(params.*ptr));
        } else {
          return params.*ptr;
        }
      },
      member);
}

[[noreturn]] void OutOfRange(const Row& row, const std::string& value) {
  throw InputError(
      fmt::format("mapper parameter {} = {} is out of range: must be {}", row.info.name, value, row.info.rule));
}

void CheckRow(const MapperParams& params, const Row& row) {
  const ParamValue value = ReadValue(params, row.member);
  if (const auto* s = std::get_if<std::string>(&value)) {
    if (std::find(row.choices.begin(), row.choices.end(), *s) == row.choices.end()) OutOfRange(row, FormatValue(value));
    return;
  }
  double v = 0;
  if (const auto* i = std::get_if<int>(&value)) v = *i;
  if (const auto* d = std::get_if<double>(&value)) v = *d;
  if (std::holds_alternative<bool>(value)) return;
  if (!InBounds(v, row.bounds)) OutOfRange(row, FormatValue(value));
}

// A rule between parameters that a set of values breaks: the parameters it involves and the
// message Validate() gives.
struct Conflict {
  std::vector<std::string> names;
  std::string message;
};

// §4.1 [DECIDE]: D/rho must be an even integer (n = D/rho + 1 odd) and 0.5 rho <= sigma <= 10 rho.
std::optional<Conflict> MatcherConflict(const std::string& prefix, double dimension, double resolution, double smear) {
  const double cells = dimension / resolution;
  const double rounded = KartoRound(cells);
  if (std::fabs(cells - rounded) > 1e-6 || static_cast<long long>(rounded) % 2 != 0) {
    return Conflict{{prefix + "_dimension", prefix + "_resolution"},
                    fmt::format("mapper parameters {0}_dimension = {1} and {0}_resolution = {2} are inconsistent: "
                                "dimension / resolution = {3} must be an even integer",
                                prefix, dimension, resolution, cells)};
  }
  if (smear < 0.5 * resolution - 1e-12 || smear > 10.0 * resolution + 1e-12) {
    return Conflict{{prefix + "_resolution", prefix + "_smear_deviation"},
                    fmt::format("mapper parameters {0}_resolution = {1} and {0}_smear_deviation = {2} are "
                                "inconsistent: the smear deviation must be in [0.5, 10] x the resolution = [{3}, {4}]",
                                prefix, resolution, smear, 0.5 * resolution, 10.0 * resolution)};
  }
  return std::nullopt;
}

// The first rule between parameters that `p` breaks, in the order Validate() checks them.
std::optional<Conflict> FirstConflict(const MapperParams& p) {
  if (p.solver == SolverKind::kCeres && p.ceres_linear_solver == CeresLinearSolver::kCgnr &&
      p.ceres_preconditioner == CeresPreconditioner::kSchurJacobi) {
    // Ceres 2.1's CGNR solver has no SCHUR_JACOBI preconditioner and aborts the process on it
    // (cgnr_solver.cc), as slam_toolbox's node does at its first solve.
    return Conflict{{"ceres_linear_solver", "ceres_preconditioner"},
                    "mapper parameters ceres_linear_solver = CGNR and ceres_preconditioner = SCHUR_JACOBI are "
                    "inconsistent: Ceres aborts on them (slam_toolbox's node crashes at its first loop closure); use "
                    "JACOBI or IDENTITY with CGNR"};
  }
  if (auto c = MatcherConflict("correlation_search_space", p.correlation_search_space_dimension,
                               p.correlation_search_space_resolution, p.correlation_search_space_smear_deviation)) {
    return c;
  }
  return MatcherConflict("loop_search_space", p.loop_search_space_dimension, p.loop_search_space_resolution,
                         p.loop_search_space_smear_deviation);
}

bool ParseBool(std::string_view text, bool* out) {
  if (text == "true" || text == "True" || text == "TRUE" || text == "1") return *out = true, true;
  if (text == "false" || text == "False" || text == "FALSE" || text == "0") return *out = false, true;
  return false;
}

bool ParseDouble(std::string_view text, double* out) {
  const char* first = text.data();
  const char* last = first + text.size();
  auto [ptr, ec] = std::from_chars(first, last, *out);
  return ec == std::errc() && ptr == last;
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

const char* NameOf(RangeThresholdRule rule) {
  switch (rule) {
    case RangeThresholdRule::kSlamKarto: return "slam_karto";
    case RangeThresholdRule::kSlamToolbox: return "slam_toolbox";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* NameOf(NodeMode mode) {
  switch (mode) {
    case NodeMode::kSlamKarto: return "slam_karto";
    case NodeMode::kSlamToolboxAsync: return "slam_toolbox_async";
    case NodeMode::kSlamToolboxSync: return "slam_toolbox_sync";
    case NodeMode::kSlamToolboxOffline: return "slam_toolbox_offline";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

bool IsSynchronous(NodeMode mode) {
  return mode == NodeMode::kSlamToolboxSync || mode == NodeMode::kSlamToolboxOffline;
}

const char* LaunchOf(NodeMode mode) {
  switch (mode) {
    case NodeMode::kSlamKarto: return "slam_karto (karto_slam.launch)";
    case NodeMode::kSlamToolboxAsync: return "slam_toolbox online_async_launch.py (asynchronous node)";
    case NodeMode::kSlamToolboxSync: return "slam_toolbox online_sync_launch.py (synchronous node)";
    case NodeMode::kSlamToolboxOffline: return "slam_toolbox offline_launch.py (synchronous node)";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* ParamTypeName(ParamType type) {
  switch (type) {
    case ParamType::kBool: return "bool";
    case ParamType::kInt: return "int";
    case ParamType::kDouble: return "double";
    case ParamType::kString: return "string";
  }
  return "?";
}

const std::vector<ParamInfo>& ParamTable() {
  static const std::vector<ParamInfo> table = [] {
    std::vector<ParamInfo> t;
    for (const Row& row : Rows()) t.push_back(row.info);
    return t;
  }();
  return table;
}

const ParamInfo* FindParam(std::string_view name) {
  for (const ParamInfo& info : ParamTable()) {
    if (name == info.name) return &info;
  }
  return nullptr;
}

ScanMatcherOptions MapperParams::SequentialMatcherOptions(double range_threshold) const {
  ScanMatcherOptions o;
  o.search_dimension = correlation_search_space_dimension;
  o.search_resolution = correlation_search_space_resolution;
  o.smear_deviation = correlation_search_space_smear_deviation;
  o.range_threshold = range_threshold;
  o.coarse_angle_offset = coarse_search_angle_offset;
  o.coarse_angle_resolution = coarse_angle_resolution;
  o.fine_angle_step = fine_search_angle_offset;
  o.distance_variance_penalty = DistanceVariancePenaltyInternal();
  o.angle_variance_penalty = AngleVariancePenaltyInternal();
  o.minimum_distance_penalty = minimum_distance_penalty;
  o.minimum_angle_penalty = minimum_angle_penalty;
  o.use_response_expansion = use_response_expansion;
  o.threads = matcher_threads;
  return o;
}

ScanMatcherOptions MapperParams::LoopMatcherOptions(double range_threshold) const {
  ScanMatcherOptions o = SequentialMatcherOptions(range_threshold);
  o.search_dimension = loop_search_space_dimension;
  o.search_resolution = loop_search_space_resolution;
  o.smear_deviation = loop_search_space_smear_deviation;
  return o;
}

OccupancyGridOptions GridOptionsOf(const MapperParams& params) {
  OccupancyGridOptions grid;
  grid.resolution = params.resolution;
  grid.min_pass_through = params.min_pass_through;
  grid.occupancy_threshold = params.occupancy_threshold;
  return grid;
}

// §9.2 and §2.1: slam_karto never sets the threshold, so Karto's 12 m is clipped into the
// laser's limits; slam_toolbox uses max_laser_range, capped at (or replaced by) range_max.
double MapperParams::RangeThreshold(double min_range, double max_range) const {
  double threshold = 12.0;
  if (range_threshold_rule == RangeThresholdRule::kSlamToolbox) {
    threshold = max_laser_range;
    if (threshold > max_range || threshold <= 0.0) threshold = max_range;
  }
  return std::clamp(threshold, min_range, std::max(min_range, max_range));
}

void MapperParams::Validate() const { Validate({}); }

void MapperParams::Validate(const UnknownChoices& unknown_choices) const {
  for (const Row& row : Rows()) {
    if (const auto unknown = unknown_choices.find(row.info.name); unknown != unknown_choices.end()) {
      OutOfRange(row, FormatValue(unknown->second));
    }
    CheckRow(*this, row);
  }
  if (const auto conflict = FirstConflict(*this)) throw InputError(conflict->message);
}

MapperParams MapperParams::Preset(std::string_view name) {
  MapperParams p;
  if (name == "slam_karto") return p;
  if (name == "open_karto") {  // §9.1 "open_karto default (internal)", converted to ROS units
    p.minimum_travel_heading = 0.17453292519943295;
    p.angle_variance_penalty = 0.3490658503988659;
    p.fine_search_angle_offset = 0.00349066;
    p.coarse_search_angle_offset = 0.349066;
    p.coarse_angle_resolution = 0.0349066;
    return p;
  }
  if (name == "slam_toolbox") {  // §9.1 "slam_toolbox YAML", §9.2
    // minimum_time_interval is a node-level filter in slam_toolbox (§3.4): its Mapper keeps 3600.
    p.minimum_travel_distance = 0.5;
    p.minimum_travel_heading = 0.5;
    p.scan_buffer_size = 10;
    p.scan_buffer_maximum_scan_distance = 10.0;
    p.link_match_minimum_response_fine = 0.1;
    p.link_scan_maximum_distance = 1.5;
    p.loop_search_maximum_distance = 3.0;
    p.loop_match_minimum_chain_size = 10;
    p.loop_match_maximum_variance_coarse = 3.0;
    p.loop_match_minimum_response_coarse = 0.35;
    p.loop_match_minimum_response_fine = 0.45;
    p.correlation_search_space_dimension = 0.5;
    p.correlation_search_space_resolution = 0.01;
    p.correlation_search_space_smear_deviation = 0.1;
    p.distance_variance_penalty = 0.5;
    p.angle_variance_penalty = 1.0;
    p.minimum_distance_penalty = 0.5;
    p.use_response_expansion = true;
    p.robot_pose_graph = true;
    p.range_threshold_rule = RangeThresholdRule::kSlamToolbox;
    p.max_laser_range = 20.0;
    p.solver = SolverKind::kCeres;
    p.ceres_preconditioner = CeresPreconditioner::kSchurJacobi;  // the shipped files' (unused by Cholesky)
    p.node_mode = NodeMode::kSlamToolboxAsync;
    p.sync_minimum_time_interval = 0.5;
    return p;
  }
  if (name == "slam_toolbox_sync" || name == "slam_toolbox_offline") {
    // The three shipped files differ only in node-level keys (map_update_interval, tf_buffer_duration).
    p = Preset("slam_toolbox");
    p.node_mode = name == "slam_toolbox_sync" ? NodeMode::kSlamToolboxSync : NodeMode::kSlamToolboxOffline;
    return p;
  }
  throw InputError(fmt::format("unknown preset '{}': must be {}", name, PresetList()));
}

const std::vector<std::string>& PresetNames() {
  static const std::vector<std::string> names = {"slam_karto", "open_karto", "slam_toolbox", "slam_toolbox_sync",
                                                 "slam_toolbox_offline"};
  return names;
}

std::string PresetList() {
  const std::vector<std::string>& names = PresetNames();
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += names[i];
    if (i + 2 < names.size()) out += ", ";
    if (i + 2 == names.size()) out += " or ";
  }
  return out;
}

std::vector<NamedParam> ToNamedValues(const MapperParams& params) {
  std::vector<NamedParam> out;
  for (const Row& row : Rows()) out.push_back({row.info.name, ReadValue(params, row.member)});
  return out;
}

double GetNumeric(const MapperParams& params, std::string_view name) {
  const Row& row = RequireRow(name);
  const ParamValue value = ReadValue(params, row.member);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? 1.0 : 0.0;
  if (const auto* i = std::get_if<int>(&value)) return *i;
  if (const auto* d = std::get_if<double>(&value)) return *d;
  throw InputError(fmt::format("mapper parameter {} is a string, not a number", name));
}

void AssignNumeric(MapperParams& copy, std::string_view name, double value) {
  const Row& row = RequireRow(name);
  const std::string shown = fmt::format("{}", value);
  std::visit(
      [&](auto ptr) {
        using T = std::remove_reference_t<decltype(copy.*ptr)>;
        if constexpr (std::is_same_v<T, bool>) {
          if (value != 0.0 && value != 1.0) OutOfRange(row, shown);
          copy.*ptr = value == 1.0;
        } else if constexpr (std::is_same_v<T, int>) {
          if (!std::isfinite(value) || value != std::floor(value) || std::fabs(value) > 1e9) OutOfRange(row, shown);
          copy.*ptr = static_cast<int>(value);
        } else if constexpr (std::is_same_v<T, double>) {
          copy.*ptr = value;
        } else {
          throw InputError(fmt::format("mapper parameter {} is a string ({}), not a number", name, row.info.rule));
        }
      },
      row.member);
}

void SetNumeric(MapperParams& params, std::string_view name, double value) {
  MapperParams copy = params;
  AssignNumeric(copy, name, value);
  copy.Validate();
  params = copy;
}

void SetNumerics(MapperParams& params, const std::map<std::string, double>& values) {
  MapperParams copy = params;
  for (const auto& [name, value] : values) AssignNumeric(copy, name, value);
  copy.Validate();
  params = copy;
}

void AssignFromString(MapperParams& copy, std::string_view name, std::string_view text,
                      UnknownChoices* unknown_choices) {
  const Row& row = RequireRow(name);
  text = Trim(text);
  std::visit(
      [&](auto ptr) {
        using T = std::remove_reference_t<decltype(copy.*ptr)>;
        if constexpr (std::is_enum_v<T>) {
          const auto choice = std::find(row.choices.begin(), row.choices.end(), text);
          if (choice != row.choices.end()) {
            copy.*ptr = static_cast<T>(choice - row.choices.begin());
            if (unknown_choices != nullptr) unknown_choices->erase(row.info.name);
          } else if (unknown_choices != nullptr) {
            (*unknown_choices)[row.info.name] = std::string(text);
          } else {
            OutOfRange(row, FormatValue(std::string(text)));
          }
        } else if constexpr (std::is_same_v<T, bool>) {
          bool b = false;
          if (!ParseBool(text, &b)) OutOfRange(row, std::string(text));
          copy.*ptr = b;
        } else {
          double v = 0;
          if (!ParseDouble(text, &v)) {
            throw InputError(fmt::format("mapper parameter {} = '{}' is not a number ({} expected, {})", name, text,
                                         ParamTypeName(row.info.type), row.info.rule));
          }
          AssignNumeric(copy, name, v);
        }
      },
      row.member);
}

void SetFromString(MapperParams& params, std::string_view name, std::string_view text) {
  MapperParams copy = params;
  UnknownChoices unknown_choices;
  AssignFromString(copy, name, text, &unknown_choices);
  copy.Validate(unknown_choices);
  params = copy;
}

namespace {

void AssignOverride(MapperParams& copy, std::string_view assignment, UnknownChoices* unknown_choices) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    throw InputError(fmt::format("parameter override '{}' must have the form name=value", assignment));
  }
  AssignFromString(copy, Trim(assignment.substr(0, eq)), assignment.substr(eq + 1), unknown_choices);
}

}  // namespace

void ApplyOverride(MapperParams& params, std::string_view assignment) {
  ApplyOverrides(params, {std::string(assignment)});
}

void ApplyOverrides(MapperParams& params, const std::vector<std::string>& assignments) {
  MapperParams copy = params;
  UnknownChoices unknown_choices;
  std::set<std::string, std::less<>> given;
  for (const std::string& a : assignments) {
    AssignOverride(copy, a, &unknown_choices);
    given.insert(RequireRow(Trim(std::string_view(a).substr(0, a.find('=')))).info.name);
  }
  try {
    copy.Validate(unknown_choices);
  } catch (const InputError& e) {
    // A rule between parameters broken by an override and a value it left as it was: say which
    // value is the base's, so that the message does not read as if the user had given it.
    const std::optional<Conflict> conflict = FirstConflict(copy);
    if (!conflict || e.message() != conflict->message) throw;
    std::string kept;
    for (const std::string& name : conflict->names) {
      if (given.count(name) == 0) kept += (kept.empty() ? "" : " and ") + name;
    }
    if (kept.empty()) throw;
    throw InputError(
        fmt::format("{} ({} {} not given with --set: the base configuration's value; set it too, or "
                    "choose values that fit it)",
                    e.message(), kept, kept.find(" and ") == std::string::npos ? "is" : "are"));
  }
  params = copy;
}

}  // namespace slamtune::slam
