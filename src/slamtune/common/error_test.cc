#include "slamtune/common/error.h"

#include <gtest/gtest.h>

namespace slamtune {
namespace {

TEST(InputError, MessageNamesFileAndLine) {
  const InputError e("log.clf", 12, "expected 180 readings, found 179");
  EXPECT_STREQ(e.what(), "log.clf:12: expected 180 readings, found 179");
  EXPECT_EQ(e.line(), 12u);
  EXPECT_EQ(e.message(), "expected 180 readings, found 179");
  EXPECT_STREQ(InputError("x.yaml", 0, "cannot open").what(), "x.yaml: cannot open");
  EXPECT_STREQ(InputError("g must be >= 1").what(), "g must be >= 1");
}

TEST(CheckDeathTest, BrokenInvariantAborts) {
  EXPECT_DEATH(SLAMTUNE_CHECK_MSG(1 + 1 == 3, "arithmetic"), "check failed: 1 \\+ 1 == 3");
}

}  // namespace
}  // namespace slamtune
