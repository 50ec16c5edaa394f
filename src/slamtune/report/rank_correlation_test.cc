#include "slamtune/report/rank_correlation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slamtune::report {
namespace {

TEST(AverageRanks, TiesShareTheMeanRank) {
  EXPECT_EQ(AverageRanks({10, 20, 20, 30}), (std::vector<double>{1, 2.5, 2.5, 4}));
  EXPECT_EQ(AverageRanks({3, 1, 2}), (std::vector<double>{3, 1, 2}));
  EXPECT_EQ(AverageRanks({5, 5, 5}), (std::vector<double>{2, 2, 2}));
  EXPECT_TRUE(AverageRanks({}).empty());
}

TEST(Spearman, PerfectMonotoneIsPlusOrMinusOne) {
  // Non-linear but monotone: rank correlation is exactly 1.
  const RankCorrelation up = SpearmanCorrelation({1, 2, 3, 4, 5}, {1, 8, 27, 64, 125});
  EXPECT_TRUE(up.defined);
  EXPECT_DOUBLE_EQ(up.rho, 1.0);
  EXPECT_EQ(up.n, 5);
  const RankCorrelation down = SpearmanCorrelation({1, 2, 3, 4, 5}, {9, 7, 5, 3, -100});
  EXPECT_DOUBLE_EQ(down.rho, -1.0);
}

TEST(Spearman, KnownValueWithoutTies) {
  // d = {0, 0, -2, 1, 1}: 1 - 6 * 6 / (5 * 24) = 0.7 (the shortcut is exact without ties).
  EXPECT_NEAR(SpearmanCorrelation({1, 2, 3, 4, 5}, {1, 2, 5, 3, 4}).rho, 0.7, 1e-12);
  // d = {1, -1, 1, -1}: 1 - 6 * 4 / (4 * 15) = 0.6.
  EXPECT_NEAR(SpearmanCorrelation({1, 2, 3, 4}, {20, 10, 40, 30}).rho, 0.6, 1e-12);
}

TEST(Spearman, KnownValueWithTies) {
  // x ranks {1, 2.5, 2.5, 4}, y ranks {1, 2, 3, 4}: Pearson of the ranks is 4.5 / sqrt(4.5 * 5).
  const RankCorrelation r = SpearmanCorrelation({1, 2, 2, 3}, {10, 20, 30, 40});
  EXPECT_NEAR(r.rho, 4.5 / std::sqrt(4.5 * 5.0), 1e-12);
  EXPECT_NEAR(r.rho, 0.9486832980505138, 1e-12);
}

TEST(Spearman, UndefinedCasesSayWhy) {
  const RankCorrelation few = SpearmanCorrelation({1, 2}, {1, 2});
  EXPECT_FALSE(few.defined);
  EXPECT_TRUE(std::isnan(few.rho));
  EXPECT_NE(few.note.find("at least 3"), std::string::npos);
  const RankCorrelation flat = SpearmanCorrelation({1, 2, 3}, {4, 4, 4});
  EXPECT_FALSE(flat.defined);
  EXPECT_NE(flat.note.find("second variable is constant"), std::string::npos);
}

TEST(Spearman, NonFinitePairsAreDropped) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const RankCorrelation r = SpearmanCorrelation({1, nan, 2, 3, 4}, {2, 5, 4, 6, 8});
  EXPECT_EQ(r.n, 4);
  EXPECT_EQ(r.dropped, 1);
  EXPECT_DOUBLE_EQ(r.rho, 1.0);
}

}  // namespace
}  // namespace slamtune::report
