#include "slamtune/slam/params_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <iterator>
#include <fstream>
#include <sstream>
#include <string_view>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// Keys of slam_karto / slam_toolbox node configurations that do not change what the engine
// computes from a log (frames, topics, timing of publication, interactive modes, ...).
constexpr std::string_view kIgnoredKeys[] = {
    "odom_frame",       "map_frame",          "base_frame",          "scan_topic",
    "scan_queue_size",  "mode",               "debug_logging",       "transform_publish_period",
    "map_update_interval", "tf_buffer_duration", "stack_size_to_use", "enable_interactive_mode",
    "ceres_linear_solver", "ceres_preconditioner", "ceres_trust_strategy", "ceres_dogleg_type",
    "map_file_name",    "map_start_pose",     "map_start_at_dock",   "use_map_saver",
    "position_covariance_scale", "yaw_covariance_scale", "use_sim_time", "transform_timeout"};

bool IsIgnored(std::string_view key) {
  return std::find(std::begin(kIgnoredKeys), std::end(kIgnoredKeys), key) != std::end(kIgnoredKeys);
}

// Finds the map that holds the parameters: `<node>: ros__parameters:`, `ros__parameters:`, or
// the document itself.
YAML::Node ParameterMap(const YAML::Node& root, const std::string& source) {
  if (!root || root.IsNull()) return YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) throw InputError(source, 0, "parameter file must be a YAML map");
  if (root["ros__parameters"]) return root["ros__parameters"];
  if (root.size() == 1) {
    const YAML::Node only = root.begin()->second;
    if (only.IsMap() && only["ros__parameters"]) return only["ros__parameters"];
  }
  return root;
}

std::string SolverFromPlugin(const std::string& plugin, const std::string& source) {
  if (plugin.find("Ceres") != std::string::npos) return "ceres";
  if (plugin.find("Spa") != std::string::npos) return "spa";
  throw InputError(source, 0,
                   fmt::format("solver_plugin '{}' is not supported: must be solver_plugins::CeresSolver or "
                               "solver_plugins::SpaSolver",
                               plugin));
}

std::string FormatForYaml(const ParamValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else if constexpr (std::is_same_v<T, double>) {
          std::string s = fmt::format("{}", v);  // shortest round-trip form
          if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep it a ROS double
          return s;
        } else {
          return fmt::format("{}", v);
        }
      },
      value);
}

}  // namespace

ParamsYamlReport ApplyParamsYaml(MapperParams& params, const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(source, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.msg);
  }
  const YAML::Node map = ParameterMap(root, source);
  if (!map.IsMap()) throw InputError(source, 0, "ros__parameters must be a YAML map");

  MapperParams copy = params;
  ParamsYamlReport report;
  const bool have_resolution = map["resolution"].IsDefined();
  for (const auto& entry : map) {
    const std::string key = entry.first.as<std::string>();
    const YAML::Node& value = entry.second;
    const std::size_t line = value.Mark().line >= 0 ? value.Mark().line + 1 : 0;
    if (!value.IsScalar()) {
      if (IsIgnored(key)) {
        report.ignored.push_back(key);
        continue;
      }
      throw InputError(source, line, fmt::format("parameter {} must be a scalar", key));
    }
    const std::string text = value.Scalar();
    try {
      if (key == "solver_plugin") {
        copy.solver = SolverFromPlugin(text, source);
        report.applied.push_back("solver");
      } else if (key == "delta") {  // slam_karto's fallback name for the map resolution
        if (have_resolution) {
          report.ignored.push_back(key);
        } else {
          SetFromString(copy, "resolution", text);
          report.applied.push_back("resolution");
        }
      } else if (FindParam(key) != nullptr) {
        SetFromString(copy, key, text);
        report.applied.push_back(key);
      } else if (IsIgnored(key)) {
        report.ignored.push_back(key);
      } else {
        throw InputError(fmt::format("unknown mapper parameter '{}'", key));
      }
    } catch (const InputError& e) {
      throw InputError(source, line, e.message());
    }
  }
  try {
    copy.Validate();
  } catch (const InputError& e) {
    throw InputError(source, 0, e.message());
  }
  params = copy;
  return report;
}

ParamsYamlReport ApplyParamsYamlFile(MapperParams& params, const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot read parameter file");
  std::ostringstream text;
  text << in.rdbuf();
  return ApplyParamsYaml(params, text.str(), path);
}

namespace {

// One "name: value" line per ROS parameter, each prefixed by `indent`.
void AppendRosParamLines(const MapperParams& params, const char* indent, std::string* out) {
  for (const NamedParam& p : ToNamedValues(params)) {
    if (!FindParam(p.name)->ros) continue;
    *out += fmt::format("{}{}: {}\n", indent, p.name, FormatForYaml(p.value));
  }
}

}  // namespace

std::string ToRosYaml(const MapperParams& params, const std::string& node_name) {
  std::string out = fmt::format("{}:\n  ros__parameters:\n", node_name);
  out += fmt::format("    solver_plugin: {}\n",
                     params.solver == "ceres" ? "solver_plugins::CeresSolver" : "solver_plugins::SpaSolver");
  AppendRosParamLines(params, "    ", &out);
  return out;
}

std::string ToFlatRosYaml(const MapperParams& params) {
  std::string out;
  if (params.solver == "ceres") {
    out += "# these values were found with the Ceres back-end; slam_karto always uses SPA\n";
  }
  AppendRosParamLines(params, "", &out);
  return out;
}

}  // namespace slamtune::slam
