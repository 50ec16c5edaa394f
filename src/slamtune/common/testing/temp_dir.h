// Temporary files and folders for a test's input and output, named so that test binaries running at
// the same time never share one.
#pragma once

#include <filesystem>
#include <string>

namespace slamtune::testing {

// Creates and returns "<tmp>/slamtune_<stem>_XXXXXX"; throws std::runtime_error when it cannot.
// A fresh, uniquely named folder (mkdtemp).
std::filesystem::path UniqueTempDir(const std::string& stem);

// "<tmp>/slamtune_<stem>_<pid>_<name>": a file path of this process (nothing is created).
std::string TempFilePath(const std::string& stem, const std::string& name);

// Writes `text` to TempFilePath(stem, name) and returns that path.
std::string WriteTempFile(const std::string& stem, const std::string& name, const std::string& text);

}  // namespace slamtune::testing
