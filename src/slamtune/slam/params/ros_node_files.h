// Parameter files for the two ROS nodes that run Karto, written so that the node loads them as
// they are and they mean there what they meant in the engine:
//
//   slam_toolbox (ROS 2, `ros2 launch slam_toolbox online_async_launch.py slam_params_file:=F`):
//     `slam_toolbox: ros__parameters:`; every value written with the type the node declares
//     for it (the literal of its declare_parameter default: ROS 2 refuses an override of
//     another type, so an int written 19.0 or a double written 3 stops the node);
//     `solver_plugin: solver_plugins::CeresSolver`, the plugin it registers; no
//     `minimum_time_interval` unless the base file sets one or the node is the synchronous one
//     (it is that node's scan filter, not Karto's: 3600 would keep one scan).
//   slam_karto (ROS 1, `rosparam load F /slam_karto` or <rosparam file=F/> in the node): a
//     flat map with the names slam_karto.cpp reads (it has no minimum_time_interval, range
//     threshold or map thresholds). The three variance values are written as the node passes
//     them to Karto, whose setters square them (Mapper.cpp setParamLoopMatchMaximumVarianceCoarse
//     etc. call math::Square), so 0.4 means 0.16 m² inside, as the shipped mapper_params.yaml
//     says; slamtune's MapperParams use the same convention.
//
// Two files per node: the full file (the base configuration with the tuned values — the user's
// own file when it is written for that node, every other key kept) and the change (only the
// parameters whose value differs from the base, to merge into the user's file). CheckNodeFile
// reads a file the way the node would and lists what would stop it or be ignored.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {

enum class RosNode { kSlamToolbox, kSlamKarto };
const char* RosNodeName(RosNode node);  // "slam_toolbox", "slam_karto"

// A parameter a node reads, with the type it declares (slam_toolbox: src/slam_mapper.cpp,
// src/slam_toolbox_common.cpp, src/laser_utils.cpp, solvers/ceres_solver.cpp; slam_karto:
// src/slam_karto.cpp). `engine` names the MapperParams field it sets ("" = none).
struct NodeParam {
  const char* name;
  ParamType type;
  const char* engine;
};
const std::vector<NodeParam>& NodeParams(RosNode node);
const NodeParam* FindNodeParam(RosNode node, std::string_view name);

// What a node uses for the parameters a file does not set: slam_toolbox's declared defaults
// (its shipped YAML's values except minimum_distance_penalty 0.05 and max_laser_range 25),
// slam_karto's open_karto defaults.
MapperParams NodeDefaults(RosNode node);

// The node a parameter file is written for: ROS 2 nesting (`<node>: ros__parameters:` or a bare
// `ros__parameters:`) means slam_toolbox, a flat map slam_karto. InputError for invalid YAML.
RosNode NodeOfParamsFile(const std::string& yaml_text, const std::string& source);

struct NodeFileInputs {
  MapperParams base;                  // what was tuned from
  MapperParams tuned;                 // base with the recommended values
  std::string base_file_text;         // the user's parameter file, or "" (a preset's defaults)
  std::vector<std::string> comments;  // header lines, written as "# ..."
  // ROS-level values from the recording, for a file made from scratch (e.g. base_frame).
  std::map<std::string, std::string> ros_level;
};

struct NodeFiles {
  std::string full;
  std::string change;
  std::vector<std::string> changed;      // "name: base -> tuned", in table order
  std::vector<std::string> not_written;  // tuned engine values the node has no parameter for
};

// The two files for `node`. With `write_change` false the change file holds only its comments
// (the recommendation is not better than the base).
NodeFiles MakeNodeFiles(RosNode node, const NodeFileInputs& in, bool write_change);

// What `node` would make of `yaml_text`: empty when it loads it; otherwise one line per problem
// (structure, unknown name, a value whose YAML type differs from the declared one, a solver
// plugin it does not register).
std::vector<std::string> CheckNodeFile(RosNode node, const std::string& yaml_text);

}  // namespace slamtune::slam
