#include "slamtune/common/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "slamtune/common/error.h"

namespace slamtune {

void WriteFileAtomically(const std::string& path, std::string_view content) {
  const std::string partial = path + ".partial";
  std::FILE* file = std::fopen(partial.c_str(), "wb");
  if (file == nullptr) throw InputError(path, 0, std::string("cannot write (") + std::strerror(errno) + ")");
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const int write_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    std::remove(partial.c_str());
    throw InputError(path, 0, std::string("cannot write (") + std::strerror(written ? errno : write_errno) + ")");
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::remove(partial.c_str());
    throw InputError(path, 0, "cannot write (" + error.message() + ")");
  }
}

}  // namespace slamtune
