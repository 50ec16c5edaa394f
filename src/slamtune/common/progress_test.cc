#include "slamtune/common/progress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace slamtune {
namespace {

std::string Capture(Progress::Mode mode, double interval) {
  std::FILE* f = std::tmpfile();
  {
    Progress p(mode, interval, f);
    p.Update("a");
    p.Update("b");
    p.Update("c", /*force=*/true);
    p.Finish("done");
  }
  std::rewind(f);
  std::string out;
  for (int c; (c = std::fgetc(f)) != EOF;) out.push_back(static_cast<char>(c));
  std::fclose(f);
  return out;
}

TEST(Progress, PlainModeThrottlesButForcedLinesPass) {
  EXPECT_EQ(Capture(Progress::Mode::kPlain, 100), "a\nc\ndone\n");
}

TEST(Progress, LiveModeRewritesOneLine) {
  const std::string out = Capture(Progress::Mode::kLive, 100);
  EXPECT_EQ(out.rfind("\ra", 0), 0u);
  EXPECT_NE(out.find("\rc"), std::string::npos);
  EXPECT_EQ(out.substr(out.size() - 6), "\ndone\n");
}

TEST(Progress, QuietPrintsNothing) { EXPECT_EQ(Capture(Progress::Mode::kQuiet, 0), ""); }

TEST(Progress, FormatsDurations) {
  EXPECT_EQ(FormatDuration(12.4), "12s");
  EXPECT_EQ(FormatDuration(185), "3m05s");
  EXPECT_EQ(FormatDuration(3720), "1h02m");
  EXPECT_EQ(FormatDuration(-1), "?");
}

TEST(FormatCount, KeepsThreeSignificantDigitsAndCarriesIntoTheNextUnit) {
  EXPECT_EQ(FormatCount(0), "0");
  EXPECT_EQ(FormatCount(950), "950");
  EXPECT_EQ(FormatCount(999.4), "999");
  EXPECT_EQ(FormatCount(999.6), "1.00 k");
  EXPECT_EQ(FormatCount(25'100), "25.1 k");
  EXPECT_EQ(FormatCount(99'960), "100 k");
  EXPECT_EQ(FormatCount(1'204'000), "1.20 M");
  EXPECT_EQ(FormatCount(999'960), "1.00 M");
  EXPECT_EQ(FormatCount(3.4e9), "3.40 G");
  EXPECT_EQ(FormatCount(-1), "?");
  EXPECT_EQ(FormatCount(std::nan("")), "?");
}

}  // namespace
}  // namespace slamtune
