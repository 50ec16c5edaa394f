#include "slamtune/common/pose2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace slamtune {
namespace {

TEST(KartoMath, RoundsHalfAwayFromZero) {
  EXPECT_EQ(KartoRound(0.5), 1.0);
  EXPECT_EQ(KartoRound(1.5), 2.0);
  EXPECT_EQ(KartoRound(2.5), 3.0);
  EXPECT_EQ(KartoRound(-0.5), -1.0);
  EXPECT_EQ(KartoRound(-2.5), -3.0);
  EXPECT_EQ(KartoRound(-0.49), 0.0);
  EXPECT_EQ(KartoRoundToInt(-1.5), -2);
}

TEST(KartoMath, EqualUsesInclusiveTolerance) {
  EXPECT_TRUE(KartoEqual(1.0, 1.0 + 0.9e-6));
  EXPECT_FALSE(KartoEqual(1.0, 1.0 + 1.1e-6));
}

// Corrupt input (an odometry heading of 1e125 rad) must not hang the loops: subtracting 2 pi
// no longer changes such a double. Angles a robot produces keep Karto's loop, bit for bit.
TEST(KartoMath, NormalizeAngleEndsOnHugeAndInfiniteAngles) {
  const double huge = NormalizeAngle(8.8e125);
  EXPECT_GE(huge, -kPi);
  EXPECT_LE(huge, kPi);
  EXPECT_TRUE(std::isnan(NormalizeAngle(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(NormalizeAngle(-std::numeric_limits<double>::infinity())));
  const double near = NormalizeAngleDifference(1e300, 0.5);
  EXPECT_LE(std::fabs(near - 0.5), kPi);
  double a = 100.0 * kPi + 0.3;  // within the loop's range: whole turns subtracted one by one
  double looped = a;
  while (looped > kPi) looped -= kTwoPi;
  EXPECT_EQ(NormalizeAngle(a), looped);
}

TEST(KartoMath, NormalizeAngleKeepsPiAndWrapsTurns) {
  EXPECT_EQ(NormalizeAngle(kPi), kPi);
  EXPECT_EQ(NormalizeAngle(-kPi), -kPi);
  EXPECT_NEAR(NormalizeAngle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(NormalizeAngle(-5 * kPi), -kPi, 1e-12);
  EXPECT_NEAR(NormalizeAngleDifference(3.0, -3.0), 3.0 - kTwoPi, 1e-12);
}

TEST(Pose2, ComposeAndBetweenAreInverse) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-5, 5), a(-kPi, kPi);
  for (int i = 0; i < 100; ++i) {
    const Pose2 p{u(rng), u(rng), a(rng)}, q{u(rng), u(rng), a(rng)};
    const Pose2 r = Compose(p, Between(p, q));
    EXPECT_NEAR(r.x, q.x, 1e-9);
    EXPECT_NEAR(r.y, q.y, 1e-9);
    EXPECT_NEAR(NormalizeAngle(r.theta - q.theta), 0.0, 1e-9);
    const Pose2 id = Compose(p, Inverse(p));
    EXPECT_NEAR(id.x, 0.0, 1e-9);
    EXPECT_NEAR(id.y, 0.0, 1e-9);
  }
}

TEST(Pose2, BetweenMatchesHandComputedValue) {
  const Pose2 a{1, 2, kPi / 2}, b{1, 3, kPi};
  const Pose2 d = Between(a, b);
  EXPECT_NEAR(d.x, 1.0, 1e-12);
  EXPECT_NEAR(d.y, 0.0, 1e-12);
  EXPECT_NEAR(d.theta, kPi / 2, 1e-12);
}

}  // namespace
}  // namespace slamtune
