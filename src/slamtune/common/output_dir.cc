#include "slamtune/common/output_dir.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "slamtune/common/error.h"

namespace slamtune {

void EnsureOutputDir(const std::string& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw InputError("--out: empty folder name; give the folder to write to");
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw InputError(dir, 0, "cannot create output folder: is a file");
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir, 0, "cannot create output folder: " + ec.message());
  const std::string probe = (fs::path(dir) / ".slamtune_write_test").string();
  std::FILE* file = std::fopen(probe.c_str(), "wb");
  if (file == nullptr) throw InputError(dir, 0, std::string("output folder is not writable: ") + std::strerror(errno));
  std::fclose(file);
  std::remove(probe.c_str());
}

}  // namespace slamtune
