// The message of the InputError a piece of test code throws, for tests that check more of it than
// one substring (the whole text, several parts, or what it leaves out). A test that only checks one
// substring uses gMock's ThrowsMessage<InputError>(HasSubstr(...)) instead.
#pragma once

#include <gtest/gtest.h>

#include <source_location>
#include <string>
#include <utility>

#include "slamtune/common/error.h"

namespace slamtune::testing {

// what() of the InputError `f` throws; when it throws none, "" and a test failure at the caller's
// line. Any other exception passes through.
template <typename F>
std::string ErrorMessageOf(F&& f, std::source_location where = std::source_location::current()) {
  try {
    std::forward<F>(f)();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE_AT(where.file_name(), static_cast<int>(where.line())) << "no InputError thrown";
  return "";
}

}  // namespace slamtune::testing
