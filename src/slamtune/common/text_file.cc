#include "slamtune/common/text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "slamtune/common/error.h"

namespace slamtune {

std::string_view StripUtf8Bom(std::string_view text) {
  if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
  return text;
}

std::string ReadWholeFile(const std::string& path) {
  if (path.empty()) throw InputError("empty file name: a file to read is required");
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw InputError(path, 0, "cannot open: is a directory");
  if (status.type() == std::filesystem::file_type::not_found) throw InputError(path, 0, "cannot open: no such file");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof(buffer), file)) > 0) text.append(buffer, got);
  const int read_errno = errno;
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(read_errno));
  return text;
}

std::string ReadTextFile(const std::string& path) {
  std::string text = ReadWholeFile(path);
  if (StripUtf8Bom(text).size() != text.size()) text.erase(0, kUtf8Bom.size());
  return text;
}

}  // namespace slamtune
