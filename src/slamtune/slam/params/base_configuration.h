// The configuration every command starts from (run, render, optimize, sweep, params): one
// loader, so that a parameter file means the same configuration to each of them and what the
// node it is written for would run.
//
//   * A parameter file is applied over the declared defaults of the node it is written for
//     (ros_node_files.h NodeOfParamsFile, NodeDefaults): ROS 2 nesting = slam_toolbox, a flat
//     map = slam_karto. --preset then only names the node's mode and must name the file's
//     node: slam_toolbox, slam_toolbox_sync or slam_toolbox_offline for a slam_toolbox file
//     (asynchronous when none is given, or the mode a file written by `slamtune optimize` names in
//     its first comment, "tuned for MODE"); slam_karto or open_karto (the same node) for a flat one.
//   * Without a file, the preset's own values (slam_karto when none is given).
//   * Then each --set NAME=VALUE, validated together.
// Folders written before this rule (BaseRule::kPresetThenFile) applied the file over the
// preset's values; resuming them keeps that.
#pragma once

#include <string>
#include <vector>

#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/params/params_yaml.h"
#include "slamtune/slam/params/ros_node_files.h"

namespace slamtune::slam {

// How a parameter file and --preset combine (see above).
enum class BaseRule { kNodeDefaults, kPresetThenFile };

struct BaseConfiguration {
  MapperParams params;
  std::string label;                   // "your configuration (FILE)", "slam_toolbox_sync's defaults", ...
  std::string file_text;               // the user's file, "" without one
  RosNode node = RosNode::kSlamKarto;  // the node the base is written for
  ParamsYamlReport file_report;        // what each key of the file meant (empty without one)
  std::string mode_source;             // how the node mode was chosen: "--preset", "FILE's first comment", "default"
};

// The base configuration of `params_file` ("" = none), `preset` ("" = the default) and `sets`.
// InputError for an unreadable or invalid file, an unknown preset, a preset of another node
// than the file's, or a bad --set.
BaseConfiguration LoadBaseConfiguration(const std::string& params_file, const std::string& preset,
                                        const std::vector<std::string>& sets, BaseRule rule = BaseRule::kNodeDefaults);

// The node a preset is for: slam_toolbox* = slam_toolbox, the others slam_karto.
RosNode NodeOfPreset(const std::string& preset);

}  // namespace slamtune::slam
