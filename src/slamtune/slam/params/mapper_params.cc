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
#include "slamtune/slam/params/mapper_param_rows.h"

namespace slamtune::slam {
namespace {

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

const ParamRow& RequireRow(std::string_view name) {
  const ParamRow* row = FindParamRow(name);
  if (row == nullptr) throw InputError(UnknownParamMessage(name));
  return *row;
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
    for (const ParamRow& row : ParamRows()) t.push_back(row.info);
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
  return {.search_dimension = correlation_search_space_dimension,
          .search_resolution = correlation_search_space_resolution,
          .smear_deviation = correlation_search_space_smear_deviation,
          .range_threshold = range_threshold,
          .coarse_angle_offset = coarse_search_angle_offset,
          .coarse_angle_resolution = coarse_angle_resolution,
          .fine_angle_step = fine_search_angle_offset,
          .distance_variance_penalty = DistanceVariancePenaltyInternal(),
          .angle_variance_penalty = AngleVariancePenaltyInternal(),
          .minimum_distance_penalty = minimum_distance_penalty,
          .minimum_angle_penalty = minimum_angle_penalty,
          .use_response_expansion = use_response_expansion,
          .threads = matcher_threads};
}

ScanMatcherOptions MapperParams::LoopMatcherOptions(double range_threshold) const {
  ScanMatcherOptions o = SequentialMatcherOptions(range_threshold);
  o.search_dimension = loop_search_space_dimension;
  o.search_resolution = loop_search_space_resolution;
  o.smear_deviation = loop_search_space_smear_deviation;
  return o;
}

OccupancyGridOptions GridOptionsOf(const MapperParams& params) {
  return {.resolution = params.resolution,
          .min_pass_through = params.min_pass_through,
          .occupancy_threshold = params.occupancy_threshold};
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
  for (const ParamRow& row : ParamRows()) {
    if (const auto unknown = unknown_choices.find(row.info.name); unknown != unknown_choices.end()) {
      ThrowParamOutOfRange(row, FormatParamValue(unknown->second));
    }
    CheckParamRow(*this, row);
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
  for (const ParamRow& row : ParamRows()) out.push_back({row.info.name, ReadParamValue(params, row.member)});
  return out;
}

double GetNumeric(const MapperParams& params, std::string_view name) {
  const ParamRow& row = RequireRow(name);
  const ParamValue value = ReadParamValue(params, row.member);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? 1.0 : 0.0;
  if (const auto* i = std::get_if<int>(&value)) return *i;
  if (const auto* d = std::get_if<double>(&value)) return *d;
  throw InputError(fmt::format("mapper parameter {} is a string, not a number", name));
}

void AssignNumeric(MapperParams& copy, std::string_view name, double value) {
  const ParamRow& row = RequireRow(name);
  const std::string shown = fmt::format("{}", value);
  std::visit(
      [&](auto ptr) {
        using T = std::remove_reference_t<decltype(copy.*ptr)>;
        if constexpr (std::is_same_v<T, bool>) {
          if (value != 0.0 && value != 1.0) ThrowParamOutOfRange(row, shown);
          copy.*ptr = value == 1.0;
        } else if constexpr (std::is_same_v<T, int>) {
          if (!std::isfinite(value) || value != std::floor(value) || std::fabs(value) > 1e9)
            ThrowParamOutOfRange(row, shown);
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
  const ParamRow& row = RequireRow(name);
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
            ThrowParamOutOfRange(row, FormatParamValue(std::string(text)));
          }
        } else if constexpr (std::is_same_v<T, bool>) {
          bool b = false;
          if (!ParseBool(text, &b)) ThrowParamOutOfRange(row, std::string(text));
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
