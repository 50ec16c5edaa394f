#include "slamtune/io/content_hash.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

uLong AddFile(uLong crc, const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  std::vector<unsigned char> buffer(1 << 20);
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), file)) > 0) {
    crc = crc32(crc, buffer.data(), static_cast<uInt>(n));
  }
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) throw InputError(path, 0, "read error");
  return crc;
}

uLong AddFolder(uLong crc, const std::string& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  if (ec) throw InputError(dir, 0, "cannot list: " + ec.message());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    const std::string name = file.filename().string() + '\0';
    crc = crc32(crc, reinterpret_cast<const Bytef*>(name.data()), static_cast<uInt>(name.size()));
    crc = AddFile(crc, file.string());
  }
  return crc;
}

}  // namespace

std::string ContentHash(const std::string& path) {
  uLong crc = crc32(0L, Z_NULL, 0);
  std::error_code ec;
  crc = std::filesystem::is_directory(path, ec) ? AddFolder(crc, path) : AddFile(crc, path);
  return fmt::format("crc32:{:08x}", static_cast<unsigned long>(crc));
}

std::map<std::string, std::string> ContentHashes(const std::map<std::string, std::string>& files) {
  std::map<std::string, std::string> hashes;
  for (const auto& [name, path] : files) {
    if (!path.empty()) hashes[name] = ContentHash(path);
  }
  return hashes;
}

void RequireSameContent(const std::map<std::string, std::string>& recorded,
                        const std::map<std::string, std::string>& files) {
  for (const auto& [name, path] : files) {
    const auto it = recorded.find(name);
    if (path.empty() || it == recorded.end()) continue;
    const std::string now = ContentHash(path);
    if (now != it->second) {
      throw InputError(path, 0,
                       fmt::format("changed since the run started (content {}, recorded {}); resuming would mix "
                                   "results of two inputs: restore the file or start a new run with --out",
                                   now, it->second));
    }
  }
}

}  // namespace slamtune::io
