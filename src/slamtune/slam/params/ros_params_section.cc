#include "slamtune/slam/params/ros_params_section.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string_view>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/yaml_text.h"

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

  // The sections are kept as iterated, not looked up again by key: a key written twice names two
  // entries, and a lookup would find the first whether or not it holds ros__parameters.
  std::vector<std::string> nodes;
  std::vector<YAML::Node> sections;
  int chosen = -1;
  int wildcard = -1;
  for (const auto& entry : root) {
    if (!entry.second.IsMap() || !entry.second["ros__parameters"]) continue;
    const std::string key = io::YamlScalarText(entry.first, source, "a node name");
    const int index = static_cast<int>(nodes.size());
    nodes.push_back(key);
    sections.push_back(entry.second["ros__parameters"]);
    if (NamesSlamToolbox(key) && chosen < 0) chosen = index;
    if (key == "/**" && wildcard < 0) wildcard = index;
  }
  if (nodes.empty()) return {root, false, ""};
  if (chosen < 0) chosen = wildcard;
  if (chosen < 0 && nodes.size() == 1) chosen = 0;
  if (chosen < 0) {
    throw InputError(
        source, LineOf(root),
        fmt::format("the file has parameters for the nodes {} and none for slam_toolbox", fmt::join(nodes, ", ")));
  }
  return Checked({sections[chosen], true, nodes[chosen]}, source);
}

}  // namespace slamtune::slam
