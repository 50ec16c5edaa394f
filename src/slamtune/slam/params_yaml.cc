#include "slamtune/slam/params_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <iterator>
#include <string_view>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/yaml_text.h"
#include "slamtune/slam/ros_node_files.h"
#include "slamtune/slam/ros_params_section.h"

namespace slamtune::slam {
namespace {

// A key of a slam_toolbox or slam_karto node configuration that does not change what the engine
// computes from a log (frames, topics, publication periods, interactive modes, ...).
bool IsNodeOnlyKey(const std::string& key) {
  for (RosNode node : {RosNode::kSlamToolbox, RosNode::kSlamKarto}) {
    const NodeParam* param = FindNodeParam(node, key);
    if (param != nullptr && param->engine[0] == '\0') return true;
  }
  return false;
}

SolverKind SolverFromPlugin(const std::string& plugin, const std::string& source) {
  if (plugin.find("Ceres") != std::string::npos) return SolverKind::kCeres;
  if (plugin.find("Spa") != std::string::npos) return SolverKind::kSpa;
  throw InputError(source, 0,
                   fmt::format("solver_plugin '{}' is not supported: must be solver_plugins::CeresSolver or "
                               "solver_plugins::SpaSolver",
                               plugin));
}

}  // namespace

ParamsYamlReport ApplyParamsYaml(MapperParams& params, const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(source, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.msg);
  }
  const ParamsSection section = FindParamsSection(root, source);
  const YAML::Node& map = section.map;
  // In a ROS 2 (slam_toolbox) file minimum_time_interval is the node's scan filter; its Karto
  // keeps 3600 (docs/engine.md §3.4).
  const bool ros2 = section.ros2;

  MapperParams copy = params;
  UnknownChoices unknown_choices;  // reported with the values out of range, after the last key
  ParamsYamlReport report;
  const bool have_resolution = map["resolution"].IsDefined();
  for (const auto& entry : map) {
    const std::string key = io::YamlScalarText(entry.first, source, "a parameter name");
    const YAML::Node& value = entry.second;
    const std::size_t line = LineOf(value);
    if (!value.IsScalar()) {
      if (IsNodeOnlyKey(key)) {
        report.ignored.push_back(key);
        continue;
      }
      throw InputError(source, line, fmt::format("parameter {} must be a scalar", key));
    }
    const std::string text = value.Scalar();
    try {
      if (ros2 && key == "minimum_time_interval") {
        report.ignored.push_back(key);
      } else if (key == "solver_plugin") {
        copy.solver = SolverFromPlugin(text, source);
        report.applied.push_back("solver");
      } else if (key == "delta") {  // slam_karto's fallback name for the map resolution
        if (have_resolution) {
          report.ignored.push_back(key);
        } else {
          AssignFromString(copy, "resolution", text, &unknown_choices);
          report.applied.push_back("resolution");
        }
      } else if (FindParam(key) != nullptr) {
        AssignFromString(copy, key, text, &unknown_choices);
        report.applied.push_back(key);
      } else if (IsNodeOnlyKey(key)) {
        report.ignored.push_back(key);
      } else {
        throw InputError(UnknownParamMessage(key));
      }
    } catch (const InputError& e) {
      throw InputError(source, line, e.message());
    }
  }
  try {
    copy.Validate(unknown_choices);
  } catch (const InputError& e) {
    throw InputError(source, 0, e.message());
  }
  params = copy;
  return report;
}

ParamsYamlReport ApplyParamsYamlFile(MapperParams& params, const std::string& path) {
  return ApplyParamsYaml(params, ReadTextFile(path), path);
}

}  // namespace slamtune::slam
