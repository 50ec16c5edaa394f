#include "slamtune/report/figures/nice_ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slamtune::report {
namespace {

TEST(NiceNumber, RoundsToOneTwoFiveTimesPowerOfTen) {
  EXPECT_DOUBLE_EQ(NiceNumber(0.13, true), 0.1);
  EXPECT_DOUBLE_EQ(NiceNumber(2.4, true), 2.0);
  EXPECT_DOUBLE_EQ(NiceNumber(4.0, true), 5.0);
  EXPECT_DOUBLE_EQ(NiceNumber(8.0, true), 10.0);
  EXPECT_DOUBLE_EQ(NiceNumber(1.2, false), 2.0);
  EXPECT_DOUBLE_EQ(NiceNumber(340.0, false), 500.0);
}

TEST(MakeNiceTicks, CoversTheDataWithWholeSteps) {
  const AxisTicks t = MakeNiceTicks(0.013, 0.087, 6);
  EXPECT_LE(t.lower, 0.013);
  EXPECT_GE(t.upper, 0.087);
  EXPECT_DOUBLE_EQ(t.step, 0.02);
  ASSERT_EQ(t.values.size(), t.labels.size());
  EXPECT_EQ(t.labels.front(), "0.00");
  EXPECT_EQ(t.labels.back(), "0.10");
  for (std::size_t i = 1; i < t.values.size(); ++i) EXPECT_NEAR(t.values[i] - t.values[i - 1], t.step, 1e-12);
}

TEST(MakeNiceTicks, IntegerDataGetsIntegerLabels) {
  const AxisTicks t = MakeNiceTicks(6, 20, 6);
  EXPECT_EQ(t.labels.front(), "5");
  EXPECT_EQ(t.labels.back(), "20");
  EXPECT_DOUBLE_EQ(t.step, 5.0);
}

TEST(MakeNiceTicks, DegenerateRangesStillGiveTwoTicks) {
  for (const auto& [lo, hi] : {std::pair{3.0, 3.0}, std::pair{0.0, 0.0}, std::pair{-2.0, -2.0}, std::pair{5.0, 1.0},
                               std::pair{std::nan(""), 1.0}, std::pair{0.0, std::numeric_limits<double>::infinity()},
                               std::pair{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max()}}) {
    const AxisTicks t = MakeNiceTicks(lo, hi, 5);
    EXPECT_GE(t.values.size(), 2u) << lo << " " << hi;
    EXPECT_GT(t.step, 0.0);
    EXPECT_LT(t.lower, t.upper);
    for (double v : t.values) EXPECT_TRUE(std::isfinite(v));
    if (std::isfinite(lo) && std::isfinite(hi) && std::abs(lo) < 1e300 && std::abs(hi) < 1e300) {
      EXPECT_LE(t.lower, std::min(lo, hi));
      EXPECT_GE(t.upper, std::max(lo, hi));
    }
  }
}

TEST(MakeTicksWithin, SpansExactlyTheLimitsWithTicksInside) {
  const AxisTicks t = MakeTicksWithin(0.05, 0.6, 5);
  EXPECT_DOUBLE_EQ(t.lower, 0.05);
  EXPECT_DOUBLE_EQ(t.upper, 0.6);
  ASSERT_GE(t.values.size(), 2u);
  EXPECT_EQ(t.values.size(), t.labels.size());
  for (double v : t.values) {
    EXPECT_GE(v, 0.05);
    EXPECT_LE(v, 0.6 + 1e-12);
  }
  EXPECT_EQ(t.labels.back(), "0.6");  // an end on a tick keeps it
}

TEST(FormatTick, CleanLabels) {
  EXPECT_EQ(FormatTick(0.1 + 0.2, 0.1), "0.3");
  EXPECT_EQ(FormatTick(-1e-17, 0.1), "0.0");
  EXPECT_EQ(FormatTick(2500.0, 500.0), "2500");
  EXPECT_EQ(FormatTick(1.5e9, 5e8), "1.5e+09");
}

}  // namespace
}  // namespace slamtune::report
