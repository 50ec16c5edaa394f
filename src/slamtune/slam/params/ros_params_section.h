// Where a ROS parameter file keeps one node's parameters.
//
// ROS 2 parameter files (rcl_yaml_param_parser, "ros__parameters") nest them under a node key:
// `slam_toolbox: ros__parameters: {...}`, also `/slam_toolbox`, a namespaced `/ns/slam_toolbox`,
// or the wildcards `/**` and `/**/slam_toolbox`; one file may hold several nodes (a robot's
// whole navigation configuration). ROS 1 (`rosparam load FILE /slam_karto`) reads a flat map.
// A bare `ros__parameters:` map at the root is read as slam_toolbox's too.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace slamtune::slam {

struct ParamsSection {
  YAML::Node map;        // the parameters (refers into the document: edits change it)
  bool ros2 = false;     // nested under ros__parameters (slam_toolbox) rather than flat (slam_karto)
  std::string node_key;  // the document's key of the node ("" for a flat map or a bare ros__parameters)
};

// The section of `root` for slam_toolbox when the file is a ROS 2 one: the node named
// slam_toolbox (any namespace), else the `/**` wildcard, else the only node in the file. A file
// with several nodes and none of those is an InputError naming them; so is a root that is not a
// map. An empty document is an empty flat map.
ParamsSection FindParamsSection(const YAML::Node& root, const std::string& source);

// The document's 1-based line of a node (0 when yaml-cpp has no position for it).
std::size_t LineOf(const YAML::Node& node);

}  // namespace slamtune::slam
