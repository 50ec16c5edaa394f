// Test helper: the error a reader of a text file gives for a file holding a given text, for the
// readers whose every message starts with the file's path (trajectory.h, relations.h).
#pragma once

#include <gtest/gtest.h>

#include <source_location>
#include <string>

#include "slamtune/common/testing/error_message.h"
#include "slamtune/common/testing/temp_dir.h"

namespace slamtune::io::testing {

// What the InputError of `read(path)` says after the path, for the temporary file `name` of the
// test `stem` holding `text`. A message that does not start with the path, or no error at all,
// is a test failure at the caller's line.
template <typename Read>
std::string ErrorAfterPath(Read read, const std::string& stem, const std::string& name, const std::string& text,
                           std::source_location where = std::source_location::current()) {
  const std::string path = slamtune::testing::WriteTempFile(stem, name, text);
  const std::string message = slamtune::testing::ErrorMessageOf([&] { read(path); }, where);
  if (message.empty()) return message;  // no error: ErrorMessageOf has failed the test
  if (!message.starts_with(path)) {
    ADD_FAILURE_AT(where.file_name(), static_cast<int>(where.line())) << "not after the path: " << message;
    return message;
  }
  return message.substr(path.size());
}

}  // namespace slamtune::io::testing
