#include "slamtune/io/yaml_text.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"

namespace slamtune::io {

std::size_t YamlLine(const YAML::Node& node) {
  return node.Mark().line >= 0 ? static_cast<std::size_t>(node.Mark().line) + 1 : 0;
}

std::string YamlScalarText(const YAML::Node& node, const std::string& source, std::string_view what) {
  if (node.IsMap() || node.IsSequence()) {
    throw InputError(source, YamlLine(node),
                     fmt::format("{} must be plain text, not a YAML {}", what, node.IsMap() ? "map" : "sequence"));
  }
  return node.as<std::string>();
}

}  // namespace slamtune::io
