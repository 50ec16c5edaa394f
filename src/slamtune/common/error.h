// Two tiers of errors (CONTRIBUTING.md, "Errors").
//
// * InputError: bad user input (a malformed log line, an out-of-range parameter, an
//   unreadable path). Carries where (file and line when known) and what; the CLI prints
//   what() on one line and exits non-zero.
// * SLAMTUNE_CHECK: a broken invariant, i.e. a programming error. Aborts loudly with the
//   condition, file and line; never used for anything a user can cause.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace slamtune {

class InputError : public std::runtime_error {
 public:
  // A problem not tied to a file position, e.g. an option value.
  explicit InputError(const std::string& message);
  // "FILE: message" (line == 0) or "FILE:LINE: message".
  InputError(const std::string& file, std::size_t line, const std::string& message);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  std::size_t line_ = 0;
  std::string message_;
};

[[noreturn]] void CheckFailed(const char* condition, const char* file, int line, const std::string& detail);

}  // namespace slamtune

// Aborts with a message when `cond` is false. For invariants only, never for user input.
#define SLAMTUNE_CHECK(cond)                                             \
  do {                                                                   \
    if (!(cond)) ::slamtune::CheckFailed(#cond, __FILE__, __LINE__, ""); \
  } while (0)
#define SLAMTUNE_CHECK_MSG(cond, detail)                                       \
  do {                                                                         \
    if (!(cond)) ::slamtune::CheckFailed(#cond, __FILE__, __LINE__, (detail)); \
  } while (0)
