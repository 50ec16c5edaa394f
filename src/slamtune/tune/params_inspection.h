// `slamtune params` as library work: what a stack of slam_toolbox or slam_karto parameter files
// means to the engine, and whether their node would load each (slam/params/ros_node_files.h
// CheckNodeFile). The files are applied in order, as a launch file stacks them (your file, then
// a change file), over the declared defaults of the first file's node.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/params/params_yaml.h"
#include "slamtune/slam/params/ros_node_files.h"

namespace slamtune::tune {

// One file of the stack.
struct ParamsFileCheck {
  std::string path;
  std::string text;
  slam::RosNode node = slam::RosNode::kSlamKarto;
  std::vector<std::string> problems;  // why the node would not take it as it is; empty: it loads
  slam::ParamsYamlReport report;      // what each key means to the engine
};

struct ParamsInspection {
  std::vector<ParamsFileCheck> files;
  slam::MapperParams params;    // the engine's parameters after every file and --set
  slam::MapperParams defaults;  // the first file's node's declared defaults, in the same mode
  std::string defaults_label;   // "slam_toolbox's declared defaults, slam_toolbox online_async_launch.py ..."

  bool AllLoad() const;
};

// Reads and checks `files` (at least one) in order with `preset`'s mode and `sets` last.
// InputError for an unreadable file, an unknown preset or a bad value.
ParamsInspection InspectParamsFiles(const std::vector<std::string>& files, const std::string& preset,
                                    const std::vector<std::string>& sets);

// The inspection as `params --json` prints it; `all`: every engine parameter, not only those that
// differ from the defaults.
nlohmann::ordered_json ToJson(const ParamsInspection& inspection, bool all);

// One engine parameter as `params` lists it.
struct ListedParam {
  std::string name;      // ROS name
  std::string value;     // true or false, a number as written by fmt, or the string
  bool differs = false;  // from inspection.defaults
};

// The engine parameters after the stack, in table order: every one with `all`, else those that
// differ from the defaults.
std::vector<ListedParam> ListedParams(const ParamsInspection& inspection, bool all);

// The value of each of check.report.keys as the file writes it ("[...]" for a sequence or a map),
// in the same order.
std::vector<std::string> WrittenValues(const ParamsFileCheck& check);

}  // namespace slamtune::tune
