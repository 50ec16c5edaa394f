// Mapper parameters from ROS YAML files (docs/engine.md §9); the files slamtune writes for
// the nodes are slam/params/ros_node_files.h's.
//
// Reads slam_toolbox's ROS 2 files (its section found as slam/params/ros_params_section.h says: node
// name, namespace, `/**`, other nodes beside it) and flat slam_karto files, as the node reads
// them:
//   * slam_toolbox's minimum_time_interval is its synchronous node's scan filter
//     (sync_minimum_time_interval), not a parameter of its Karto, and when a file leaves it out
//     the node takes transform_timeout's value for it;
//   * slam_toolbox's ceres_* texts are mapped as CeresSolver::Configure maps them: a text it
//     does not know means the node's default (CeresChoices), said in a warning;
//   * the nodes' own keys that do not change the map (frames, topics, publish periods, ...;
//     slam/params/ros_node_files.h's tables) are read and listed as such; keys that change what the
//     node maps but that the engine does not reproduce (continuing a saved map, localization)
//     are listed as not modelled, with a warning.
// Any other unknown key, a wrong type or an out-of-range value throws InputError naming the
// file, the line, the parameter and the rule. The values are checked together, after all are
// applied. Every key of the file is listed in the report with what it means to the engine.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {

// What a key of a parameter file means for the map (`slamtune params` prints it for each key).
enum class KeyUse {
  kEngine,       // read by the engine as the node reads it
  kNodeOnly,     // the node reads it, and it changes nothing on the map
  kNotModelled,  // it changes what the node maps, and the engine does not reproduce that
};
// "used by the engine", "node-only (no effect on the map)", "not modelled".
const char* NameOf(KeyUse use);

struct KeyReport {
  std::string key;       // as written
  std::size_t line = 0;  // 1-based; 0 when unknown
  KeyUse use = KeyUse::kEngine;
  std::string note;  // why, or what the node makes of the value; "" when plain
};

struct ParamsYamlReport {
  std::vector<std::string> applied;   // engine parameter names set from the file, in file order
  std::vector<std::string> ignored;   // keys that change nothing on the map
  std::vector<KeyReport> keys;        // every key of the file, in file order
  std::vector<std::string> warnings;  // "FILE:LINE: ..." for values the node reads otherwise than
                                      // written and for keys not modelled
};

// Applies the parameters found in YAML text to `params`; on error `params` is unchanged.
// `source` names the text in messages. How a key is read may depend on params.node_mode (e.g.
// throttle_scans is node-only for slam_toolbox's asynchronous node), so set the mode first.
ParamsYamlReport ApplyParamsYaml(MapperParams& params, const std::string& yaml_text, const std::string& source);
// Same, reading a file. Throws InputError if it cannot be read.
ParamsYamlReport ApplyParamsYamlFile(MapperParams& params, const std::string& path);

}  // namespace slamtune::slam
