// Paths of the committed test inputs, tests/fixtures/ of the source tree.
#pragma once

#include <string>

namespace slamtune::testing {

// tests/fixtures/<relative>, e.g. FixturePath("recordings/office_db3"). SLAMTUNE_SOURCE_DIR is
// defined for every test executable.
inline std::string FixturePath(const std::string& relative) {
  return std::string(SLAMTUNE_SOURCE_DIR) + "/tests/fixtures/" + relative;
}

}  // namespace slamtune::testing
