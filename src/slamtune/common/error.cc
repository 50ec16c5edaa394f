#include "slamtune/common/error.h"

#include <cstdio>
#include <cstdlib>

namespace slamtune {
namespace {

std::string Locate(const std::string& file, std::size_t line, const std::string& message) {
  if (file.empty()) return message;
  if (line == 0) return file + ": " + message;
  return file + ":" + std::to_string(line) + ": " + message;
}

}  // namespace

InputError::InputError(const std::string& message) : std::runtime_error(message), message_(message) {}

InputError::InputError(const std::string& file, std::size_t line, const std::string& message)
    : std::runtime_error(Locate(file, line, message)), file_(file), line_(line), message_(message) {}

void CheckFailed(const char* condition, const char* file, int line, const std::string& detail) {
  std::fprintf(stderr, "slamtune: internal error: check failed: %s at %s:%d%s%s\n", condition, file, line,
               detail.empty() ? "" : ": ", detail.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace slamtune
