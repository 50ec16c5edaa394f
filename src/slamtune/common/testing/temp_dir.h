// A fresh, uniquely named folder under the system's temporary directory for a test's output
// (mkdtemp), so that test binaries running at the same time never share a folder.
#pragma once

#include <filesystem>
#include <string>

namespace slamtune::testing {

// Creates and returns "<tmp>/slamtune_<stem>_XXXXXX"; throws std::runtime_error when it cannot.
std::filesystem::path UniqueTempDir(const std::string& stem);

}  // namespace slamtune::testing
