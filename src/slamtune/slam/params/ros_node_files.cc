#include "slamtune/slam/params/ros_node_files.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "slamtune/common/error.h"
#include "slamtune/slam/params/mapper_param_rows.h"
#include "slamtune/slam/params/ros_params_section.h"

namespace slamtune::slam {
namespace {

using enum ParamType;

// Karto's mapper parameters, read under the same names and types by both nodes.
#define MAPPER_PARAMS                                                                                                \
  {"use_scan_matching", kBool, "use_scan_matching"}, {"use_scan_barycenter", kBool, "use_scan_barycenter"},          \
      {"minimum_travel_distance", kDouble, "minimum_travel_distance"},                                               \
      {"minimum_travel_heading", kDouble, "minimum_travel_heading"}, {"scan_buffer_size", kInt, "scan_buffer_size"}, \
      {"scan_buffer_maximum_scan_distance", kDouble, "scan_buffer_maximum_scan_distance"},                           \
      {"link_match_minimum_response_fine", kDouble, "link_match_minimum_response_fine"},                             \
      {"link_scan_maximum_distance", kDouble, "link_scan_maximum_distance"},                                         \
      {"loop_search_maximum_distance", kDouble, "loop_search_maximum_distance"},                                     \
      {"do_loop_closing", kBool, "do_loop_closing"},                                                                 \
      {"loop_match_minimum_chain_size", kInt, "loop_match_minimum_chain_size"},                                      \
      {"loop_match_maximum_variance_coarse", kDouble, "loop_match_maximum_variance_coarse"},                         \
      {"loop_match_minimum_response_coarse", kDouble, "loop_match_minimum_response_coarse"},                         \
      {"loop_match_minimum_response_fine", kDouble, "loop_match_minimum_response_fine"},                             \
      {"correlation_search_space_dimension", kDouble, "correlation_search_space_dimension"},                         \
      {"correlation_search_space_resolution", kDouble, "correlation_search_space_resolution"},                       \
      {"correlation_search_space_smear_deviation", kDouble, "correlation_search_space_smear_deviation"},             \
      {"loop_search_space_dimension", kDouble, "loop_search_space_dimension"},                                       \
      {"loop_search_space_resolution", kDouble, "loop_search_space_resolution"},                                     \
      {"loop_search_space_smear_deviation", kDouble, "loop_search_space_smear_deviation"},                           \
      {"distance_variance_penalty", kDouble, "distance_variance_penalty"},                                           \
      {"angle_variance_penalty", kDouble, "angle_variance_penalty"},                                                 \
      {"fine_search_angle_offset", kDouble, "fine_search_angle_offset"},                                             \
      {"coarse_search_angle_offset", kDouble, "coarse_search_angle_offset"},                                         \
      {"coarse_angle_resolution", kDouble, "coarse_angle_resolution"},                                               \
      {"minimum_angle_penalty", kDouble, "minimum_angle_penalty"},                                                   \
      {"minimum_distance_penalty", kDouble, "minimum_distance_penalty"}, {                                           \
    "use_response_expansion", kBool, "use_response_expansion"                                                        \
  }

const std::vector<NodeParam>& ToolboxParams() {
  static const std::vector<NodeParam> params = {
      // node (slam_toolbox_common.cpp, laser_utils.cpp, main), then the solver and the mapper
      {"odom_frame", kString, ""},
      {"map_frame", kString, ""},
      {"base_frame", kString, ""},
      {"scan_topic", kString, ""},
      {"scan_queue_size", kInt, ""},
      {"mode", kString, ""},
      {"debug_logging", kBool, ""},
      {"throttle_scans", kInt, "throttle_scans"},
      {"transform_publish_period", kDouble, ""},
      {"map_update_interval", kDouble, ""},
      {"resolution", kDouble, "resolution"},
      {"min_laser_range", kDouble, "min_laser_range"},
      {"max_laser_range", kDouble, "max_laser_range"},
      {"minimum_time_interval", kDouble, "sync_minimum_time_interval"},
      {"transform_timeout", kDouble, ""},
      {"tf_buffer_duration", kDouble, ""},
      {"stack_size_to_use", kInt, ""},
      {"enable_interactive_mode", kBool, ""},
      {"position_covariance_scale", kDouble, ""},
      {"yaw_covariance_scale", kDouble, ""},
      {"map_name", kString, ""},
      {"map_file_name", kString, ""},
      {"map_start_at_dock", kBool, ""},
      {"map_start_pose", kDouble, ""} /* a list [x, y, theta] */,
      {"use_map_saver", kBool, ""},
      {"paused_new_measurements", kBool, ""},
      {"use_sim_time", kBool, ""},
      {"min_pass_through", kInt, "min_pass_through"},
      {"occupancy_threshold", kDouble, "occupancy_threshold"},
      {"solver_plugin", kString, "solver"},
      {"ceres_linear_solver", kString, "ceres_linear_solver"},
      {"ceres_preconditioner", kString, "ceres_preconditioner"},
      {"ceres_trust_strategy", kString, "ceres_trust_strategy"},
      {"ceres_dogleg_type", kString, "ceres_dogleg_type"},
      {"ceres_loss_function", kString, "ceres_loss_function"},
      MAPPER_PARAMS};
  return params;
}

const std::vector<NodeParam>& KartoParams() {
  // slam_karto.cpp's SlamKarto::SlamKarto reads these from its private namespace; with scan
  // times never set, minimum_time_interval only matters when ≤ 0 (docs/engine.md §3.4).
  static const std::vector<NodeParam> params = {{"odom_frame", kString, ""},
                                                {"map_frame", kString, ""},
                                                {"base_frame", kString, ""},
                                                {"throttle_scans", kInt, "throttle_scans"},
                                                {"map_update_interval", kDouble, ""},
                                                {"transform_tolerance", kDouble, ""},
                                                {"resolution", kDouble, "resolution"},
                                                {"delta", kDouble, ""},
                                                {"transform_publish_period", kDouble, ""},
                                                {"minimum_time_interval", kDouble, ""},
                                                MAPPER_PARAMS};
  return params;
}
#undef MAPPER_PARAMS

constexpr const char* kCeresPlugin = "solver_plugins::CeresSolver";  // the one slam_toolbox registers
// The value of an engine field as the node's declared type writes it.
std::string Typed(ParamType type, const ParamValue& value) {
  const double* real = std::get_if<double>(&value);
  const int* whole = std::get_if<int>(&value);
  if (real == nullptr && whole == nullptr) return ParamValueText(value);
  const double d = real != nullptr ? *real : *whole;
  if (type == kInt) return fmt::format("{}", static_cast<long long>(std::llround(d)));
  if (type == kBool) return d != 0.0 ? "true" : "false";
  std::string s = fmt::format("{}", d);  // shortest round trip
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

ParamValue EngineValue(const MapperParams& p, const std::string& field) {
  for (const NamedParam& named : ToNamedValues(p)) {
    if (named.name == field) return named.value;
  }
  SLAMTUNE_CHECK_MSG(false, "no engine parameter " + field);
  return 0;
}

// The text a node parameter takes from `p` (solver_plugin from the engine's back-end).
std::string NodeValue(const NodeParam& param, const MapperParams& p) {
  if (std::string_view(param.name) == "solver_plugin") return kCeresPlugin;
  return Typed(param.type, EngineValue(p, param.engine));
}

// Whether a file made or completed by slamtune writes `param`: slam_toolbox's minimum_time_interval
// only for the synchronous node, the one that reads it (the asynchronous node never does, and
// a value written there would only mislead).
bool Writes(const NodeParam& param, const MapperParams& p) {
  return param.engine[0] != '\0' &&
         (std::string_view(param.name) != "minimum_time_interval" || IsSynchronous(p.node_mode));
}

bool Differs(const NodeParam& param, const MapperParams& a, const MapperParams& b) {
  return param.engine[0] != '\0' && std::string_view(param.name) != "solver_plugin" &&
         EngineValue(a, param.engine) != EngineValue(b, param.engine);
}

std::string Comments(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += "# " + line + "\n";
  return out;
}

std::string Emit(const YAML::Node& node) {
  YAML::Emitter out;
  out << node;
  return std::string(out.c_str()) + "\n";
}

// "name: value" lines with `indent`.
std::string Lines(const std::vector<std::pair<std::string, std::string>>& entries, const char* indent) {
  std::string out;
  for (const auto& [name, value] : entries) out += fmt::format("{}{}: {}\n", indent, name, value);
  return out;
}

std::string Wrap(RosNode node, const std::string& body) {
  if (node == RosNode::kSlamKarto) return body;
  return "slam_toolbox:\n  ros__parameters:\n" + (body.empty() ? std::string("    {}\n") : body);
}

// A file made from scratch: the node's ROS-level values from the recording, then every
// parameter the engine sets, from `p`.
std::string ScratchFile(RosNode node, const MapperParams& p, const std::map<std::string, std::string>& ros_level) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const NodeParam& param : NodeParams(node)) {
    const std::string name = param.name;
    auto it = ros_level.find(name);
    if (it != ros_level.end() && param.engine[0] == '\0') entries.emplace_back(name, it->second);
    if (!Writes(param, p)) continue;
    entries.emplace_back(name, NodeValue(param, p));
  }
  if (node == RosNode::kSlamToolbox) entries.insert(entries.begin(), {"mode", "mapping"});
  return Wrap(node, Lines(entries, node == RosNode::kSlamKarto ? "" : "    "));
}

// The user's file emitted again by yaml-cpp (its comments are lost): for layouts that cannot
// be edited line by line (flow maps, values over several lines).
std::string ReEmitted(RosNode node, YAML::Node root, const ParamsSection& section, const MapperParams& p) {
  YAML::Node map = section.map;
  for (const NodeParam& param : NodeParams(node)) {
    const bool present = static_cast<const YAML::Node&>(map)[param.name].IsDefined();
    if (param.engine[0] == '\0' || (!Writes(param, p) && !present)) continue;
    map[param.name] = NodeValue(param, p);
  }
  if (node == RosNode::kSlamToolbox && section.node_key.empty()) {
    YAML::Node wrapped;
    wrapped["slam_toolbox"]["ros__parameters"] = map;
    return Emit(wrapped);
  }
  return Emit(root);
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    lines.push_back(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return lines;
}

// The end column of the one-line scalar starting at `col` of `line` (quoted, or plain up to a
// comment), or npos when the scalar does not end on this line.
std::size_t ScalarEnd(const std::string& line, std::size_t col) {
  if (col >= line.size()) return std::string::npos;
  const char quote = line[col];
  if (quote == '\'' || quote == '"') {
    for (std::size_t i = col + 1; i < line.size(); ++i) {
      if (quote == '"' && line[i] == '\\') {
        ++i;
      } else if (line[i] == quote) {
        if (quote == '\'' && i + 1 < line.size() && line[i + 1] == '\'') {
          ++i;
        } else {
          return i + 1;
        }
      }
    }
    return std::string::npos;
  }
  std::size_t end = line.find(" #", col);
  if (end == std::string::npos) end = line.size();
  while (end > col && (line[end - 1] == ' ' || line[end - 1] == '\t' || line[end - 1] == '\r')) --end;
  return end;
}

struct LineEdit {
  std::size_t line, begin, end;
  std::string text;
};

// The user's file with each parameter the engine sets rewritten in place (typed as the node
// declares) and the missing ones appended to its section: every other key, comment and line
// stays as the user wrote it. Falls back to ReEmitted for layouts it cannot edit by line.
std::string FromBaseFile(RosNode node, const std::string& text, const MapperParams& p) {
  YAML::Node root = YAML::Load(text);
  const ParamsSection section = FindParamsSection(root, "base");
  const YAML::Node& map = section.map;
  if (!map.IsMap() || map.size() == 0 || map.Style() == YAML::EmitterStyle::Flow) {
    return ReEmitted(node, root, section, p);
  }
  std::vector<std::string> lines = SplitLines(text);
  std::vector<LineEdit> edits;
  std::vector<std::string> present;
  std::size_t last_line = 0;
  std::size_t indent = std::string::npos;
  for (const auto& entry : map) {
    const YAML::Mark key_mark = entry.first.Mark();
    const YAML::Mark mark = entry.second.Mark();
    if (key_mark.line < 0 || mark.line < 0) return ReEmitted(node, root, section, p);
    if (indent == std::string::npos) indent = static_cast<std::size_t>(key_mark.column);
    last_line = std::max(last_line, static_cast<std::size_t>(mark.line));
    const std::string name = entry.first.as<std::string>();
    const NodeParam* param = FindNodeParam(node, name);
    if (param == nullptr || param->engine[0] == '\0') continue;
    present.push_back(name);
    const auto line = static_cast<std::size_t>(mark.line);
    const auto col = static_cast<std::size_t>(mark.column);
    if (!entry.second.IsScalar() || line >= lines.size()) return ReEmitted(node, root, section, p);
    const std::size_t end = ScalarEnd(lines[line], col);
    if (end == std::string::npos) return ReEmitted(node, root, section, p);
    edits.push_back({line, col, end, NodeValue(*param, p)});
  }
  // A value of several lines would put the appended keys inside it.
  if (last_line >= lines.size() || ScalarEnd(lines[last_line], 0) == std::string::npos) {
    return ReEmitted(node, root, section, p);
  }
  std::sort(edits.begin(), edits.end(), [](const LineEdit& a, const LineEdit& b) {
    return a.line != b.line ? a.line > b.line : a.begin > b.begin;
  });
  for (const LineEdit& e : edits) lines[e.line].replace(e.begin, e.end - e.begin, e.text);
  std::vector<std::string> added;
  for (const NodeParam& param : NodeParams(node)) {
    if (!Writes(param, p) || std::find(present.begin(), present.end(), param.name) != present.end()) continue;
    added.push_back(fmt::format("{}{}: {}", std::string(indent, ' '), param.name, NodeValue(param, p)));
  }
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(last_line) + 1, added.begin(), added.end());
  const bool wrap = node == RosNode::kSlamToolbox && section.node_key.empty();
  std::string out = wrap ? "slam_toolbox:\n" : "";
  for (const std::string& line : lines) out += (wrap && !line.empty() ? "  " : "") + line + "\n";
  return out;
}

bool IsInt(const std::string& s) { return std::regex_match(s, std::regex("[-+]?[0-9]+")); }
bool IsFloat(const std::string& s) {
  return std::regex_match(s, std::regex("[-+]?([0-9]+\\.[0-9]*|\\.[0-9]+|[0-9]+)([eE][-+]?[0-9]+)?")) ||
         std::regex_match(s, std::regex("[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|NAN)"));
}
bool IsBool(const std::string& s) {
  static const char* kWords[] = {"true", "True", "TRUE", "false", "False", "FALSE", "yes", "Yes", "YES",
                                 "no",   "No",   "NO",   "on",    "On",    "ON",    "off", "Off", "OFF"};
  return std::find(std::begin(kWords), std::end(kWords), s) != std::end(kWords);
}

// The YAML type a node's parser gives a scalar (a quoted one is a string).
ParamType ScalarType(const YAML::Node& value) {
  const std::string s = value.Scalar();
  if (value.Tag() == "!") return kString;
  if (IsBool(s)) return kBool;
  if (IsInt(s)) return kInt;
  if (IsFloat(s)) return kDouble;
  return kString;
}

}  // namespace

const char* RosNodeName(RosNode node) { return node == RosNode::kSlamToolbox ? "slam_toolbox" : "slam_karto"; }

const std::vector<NodeParam>& NodeParams(RosNode node) {
  return node == RosNode::kSlamToolbox ? ToolboxParams() : KartoParams();
}

const NodeParam* FindNodeParam(RosNode node, std::string_view name) {
  for (const NodeParam& p : NodeParams(node)) {
    if (name == p.name) return &p;
  }
  return nullptr;
}

MapperParams NodeDefaults(RosNode node) {
  if (node == RosNode::kSlamKarto) return MapperParams::Preset("open_karto");
  MapperParams p = MapperParams::Preset("slam_toolbox");
  p.minimum_distance_penalty = 0.05;                      // slam_mapper.cpp's declared default (its YAML writes 0.5)
  p.max_laser_range = 25.0;                               // laser_utils.cpp's declared default (its YAML writes 20.0)
  p.ceres_preconditioner = CeresPreconditioner::kJacobi;  // ceres_solver.cpp's (its YAML: SCHUR_JACOBI)
  p.sync_minimum_time_interval = 0.5;                     // transform_timeout's declared 0.5 (slam_toolbox_common.cpp)
  return p;
}

RosNode NodeOfParamsFile(const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(source, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.msg);
  }
  return FindParamsSection(root, source).ros2 ? RosNode::kSlamToolbox : RosNode::kSlamKarto;
}

NodeFiles MakeNodeFiles(RosNode node, const NodeFileInputs& in, bool write_change) {
  NodeFiles files;
  const std::string header = Comments(in.comments);
  const bool own_file = !in.base_file_text.empty() && NodeOfParamsFile(in.base_file_text, "base") == node;
  files.full =
      header + (own_file ? FromBaseFile(node, in.base_file_text, in.tuned) : ScratchFile(node, in.tuned, in.ros_level));
  std::vector<std::pair<std::string, std::string>> change;
  for (const NodeParam& param : NodeParams(node)) {
    if (!Differs(param, in.base, in.tuned)) continue;
    files.changed.push_back(
        fmt::format("{}: {} -> {}", param.name, NodeValue(param, in.base), NodeValue(param, in.tuned)));
    change.emplace_back(param.name, NodeValue(param, in.tuned));
  }
  for (const NamedParam& named : ToNamedValues(in.tuned)) {
    const bool differs = EngineValue(in.base, named.name) != named.value;
    const bool has_param = std::any_of(NodeParams(node).begin(), NodeParams(node).end(),
                                       [&](const NodeParam& p) { return named.name == p.engine; });
    if (differs && !has_param) files.not_written.push_back(named.name);
  }
  files.change = header;
  if (write_change && !change.empty()) {
    files.change += Wrap(node, Lines(change, node == RosNode::kSlamKarto ? "" : "    "));
  }
  return files;
}

std::vector<std::string> CheckNodeFile(RosNode node, const std::string& yaml_text) {
  std::vector<std::string> problems;
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    return {fmt::format("not valid YAML: {}", e.msg)};
  }
  if (!root || root.IsNull()) return problems;  // a file of comments only sets nothing
  if (!root.IsMap()) return {"the file is not a YAML map"};
  ParamsSection section;
  try {
    section = FindParamsSection(root, "file");
  } catch (const InputError& e) {
    return {e.message()};
  }
  if (node == RosNode::kSlamToolbox && (!section.ros2 || section.node_key.empty())) {
    return {"a slam_toolbox file nests its parameters as slam_toolbox: ros__parameters: {...}"};
  }
  if (node == RosNode::kSlamKarto && section.ros2) {
    return {"a slam_karto file is a flat map (rosparam load FILE /slam_karto)"};
  }
  if (!section.map.IsMap()) return problems;  // `ros__parameters:` with nothing in it
  const YAML::Node& map = section.map;
  for (const auto& entry : map) {
    const std::string name = entry.first.as<std::string>();
    const NodeParam* param = FindNodeParam(node, name);
    if (param == nullptr) {
      problems.push_back(fmt::format("{}: not a {} parameter", name, RosNodeName(node)));
      continue;
    }
    const YAML::Node& value = entry.second;
    if (!value.IsScalar()) {
      if (name != "map_start_pose") problems.push_back(fmt::format("{}: must be a single value", name));
      continue;
    }
    const ParamType got = ScalarType(value);
    // ROS 2 refuses any other type than the declared one; ROS 1's getParam(double) takes an int.
    const bool ok = got == param->type || (node == RosNode::kSlamKarto && param->type == kDouble && got == kInt);
    if (!ok) {
      problems.push_back(fmt::format("{}: '{}' reads as {}, the node declares {}", name, value.Scalar(),
                                     ParamTypeName(got), ParamTypeName(param->type)));
    }
    if (name == "solver_plugin" && value.Scalar() != kCeresPlugin) {
      problems.push_back(
          fmt::format("solver_plugin: '{}' is not registered by slam_toolbox (only {})", value.Scalar(), kCeresPlugin));
    }
  }
  return problems;
}

}  // namespace slamtune::slam
