// The text of a YAML key or scalar in the files slamtune reads (parameter files, search spaces).
//
// yaml-cpp answers `as<std::string>()` on a map or sequence with its own exception
// (TypedBadConversion), which is not an InputError: a file with `{a: 1}: 2` or `[x]: 3` in place
// of a name would end the program instead of naming the line. Readers take keys through this.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace slamtune::io {

// The node's 1-based line (0 when yaml-cpp has no position for it).
std::size_t YamlLine(const YAML::Node& node);

// The scalar text of `node` (a null node reads "null", as yaml-cpp writes it). A map or sequence
// throws InputError "SOURCE:LINE: WHAT must be plain text, not a YAML map" (or "sequence").
std::string YamlScalarText(const YAML::Node& node, const std::string& source, std::string_view what);

}  // namespace slamtune::io
