// Mapper parameters from and to ROS YAML files (karto-algorithm.md §9).
//
// Reads the ROS 2 nesting (`<node>: ros__parameters: {...}`, e.g. slam_toolbox's shipped
// mapper_params_*.yaml), a bare `ros__parameters:` map, and a flat map (slam_karto's
// config/mapper_params.yaml). Keys of the ROS nodes that do not change the engine (frames,
// topics, publish periods, ...) are recognised and ignored (listed in the result); any other
// unknown key, a wrong type or an out-of-range value throws InputError naming the file, the
// parameter and the rule.
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

// The ROS parameters (ParamInfo::ros) in slam_toolbox's nesting, `node_name: ros__parameters:`,
// plus `solver_plugin`. Values round-trip exactly.
std::string ToRosYaml(const MapperParams& params, const std::string& node_name = "slam_toolbox");
// The same ROS parameters as a flat map, the form of slam_karto's config/mapper_params.yaml
// (ROS 1: `rosparam load FILE /slam_karto`, or <rosparam file=.../> inside the node). slam_karto
// always solves with SPA, so there is no solver key; a comment says so when `params` use
// Ceres. Values round-trip exactly (ApplyParamsYaml reads flat maps).
std::string ToFlatRosYaml(const MapperParams& params);

}  // namespace slamtune::slam
