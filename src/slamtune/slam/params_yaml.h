// Mapper parameters from ROS YAML files (docs/engine.md §9); the files slamtune writes for
// the nodes are slam/ros_node_files.h's.
//
// Reads slam_toolbox's ROS 2 files (its section found as slam/ros_params_section.h says: node
// name, namespace, `/**`, other nodes beside it) and flat slam_karto files. In a ROS 2 file
// minimum_time_interval is slam_toolbox's node-level scan filter, not a parameter of its Karto:
// it is listed as ignored. The nodes' own keys that do not change the engine (frames, topics,
// publish periods, ...; slam/ros_node_files.h's tables) are ignored and listed; any other
// unknown key, a wrong type or an out-of-range value throws InputError naming the file, the
// parameter and the rule. The values are checked together, after all are applied.
#pragma once

#include <string>
#include <vector>

#include "slamtune/slam/mapper_params.h"

namespace slamtune::slam {

struct ParamsYamlReport {
  std::vector<std::string> applied;  // parameter names set from the file, in file order
  std::vector<std::string> ignored;  // recognised ROS node keys that do not affect the engine
};

// Applies the parameters found in YAML text to `params`; on error `params` is unchanged.
// `source` names the text in error messages.
ParamsYamlReport ApplyParamsYaml(MapperParams& params, const std::string& yaml_text, const std::string& source);
// Same, reading a file. Throws InputError if it cannot be read.
ParamsYamlReport ApplyParamsYamlFile(MapperParams& params, const std::string& path);

}  // namespace slamtune::slam
