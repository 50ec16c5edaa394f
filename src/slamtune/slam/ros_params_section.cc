#include "slamtune/slam/ros_params_section.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string_view>
#include <vector>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// "slam_toolbox", "/slam_toolbox", "/robot1/slam_toolbox", "/**/slam_toolbox".
bool NamesSlamToolbox(std::string_view key) {
  const std::size_t slash = key.rfind('/');
  return (slash == std::string_view::npos ? key : key.substr(slash + 1)) == "slam_toolbox";
}

std::size_t LineOfNode(const YAML::Node& node) {
  return node.Mark().line >= 0 ? static_cast<std::size_t>(node.Mark().line) + 1 : 0;
}

ParamsSection Checked(ParamsSection section, const std::string& source) {
  if (!section.map.IsMap() && !section.map.IsNull()) {
    throw InputError(source, LineOfNode(section.map), "ros__parameters must be a YAML map");
  }
  return section;
}

}  // namespace

std::size_t LineOf(const YAML::Node& node) { return LineOfNode(node); }

ParamsSection FindParamsSection(const YAML::Node& root, const std::string& source) {
  if (!root || root.IsNull()) return {YAML::Node(YAML::NodeType::Map), false, ""};
  if (!root.IsMap()) throw InputError(source, LineOf(root), "a parameter file must be a YAML map");
  if (root["ros__parameters"]) return Checked({root["ros__parameters"], true, ""}, source);

  std::vector<std::string> nodes;
  std::string chosen;
  std::string wildcard;
  for (const auto& entry : root) {
    if (!entry.second.IsMap() || !entry.second["ros__parameters"]) continue;
    const std::string key = entry.first.as<std::string>();
    nodes.push_back(key);
    if (NamesSlamToolbox(key) && chosen.empty()) chosen = key;
    if (key == "/**" && wildcard.empty()) wildcard = key;
  }
  if (nodes.empty()) return {root, false, ""};
  if (chosen.empty()) chosen = wildcard;
  if (chosen.empty() && nodes.size() == 1) chosen = nodes.front();
  if (chosen.empty()) {
    throw InputError(source, LineOf(root),
                     fmt::format("the file has parameters for the nodes {} and none for slam_toolbox",
                                 fmt::join(nodes, ", ")));
  }
  return Checked({root[chosen]["ros__parameters"], true, chosen}, source);
}

}  // namespace slamtune::slam
