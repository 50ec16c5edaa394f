#include "slamtune/common/testing/temp_dir.h"

#include <stdlib.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <vector>

namespace slamtune::testing {

std::filesystem::path UniqueTempDir(const std::string& stem) {
  const std::string pattern = (std::filesystem::temp_directory_path() / ("slamtune_" + stem + "_XXXXXX")).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (::mkdtemp(buffer.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
  return std::filesystem::path(buffer.data());
}

std::string TempFilePath(const std::string& stem, const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("slamtune_" + stem + "_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

std::string WriteTempFile(const std::string& stem, const std::string& name, const std::string& text) {
  const std::string path = TempFilePath(stem, name);
  std::ofstream(path) << text;
  return path;
}

}  // namespace slamtune::testing
