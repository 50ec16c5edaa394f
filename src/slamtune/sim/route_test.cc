#include "slamtune/sim/route.h"

#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

using V = Eigen::Vector2d;

TEST(Route, StraightLineHasExactPoses) {
  const Route route({V(1, 1), V(4, 5)}, 0.5);
  EXPECT_DOUBLE_EQ(route.length(), 5.0);
  const Pose2 mid = route.PoseAt(2.5);
  EXPECT_NEAR(mid.x, 2.5, 1e-12);
  EXPECT_NEAR(mid.y, 3.0, 1e-12);
  EXPECT_NEAR(mid.theta, std::atan2(4.0, 3.0), 1e-12);
  EXPECT_NEAR(route.PoseAt(99.0).x, 4.0, 1e-12);  // clamped to the end
}

TEST(Route, RightAngleCornerIsAQuarterCircle) {
  // (0,0) -> (10,0) -> (10,10), radius 1: the arc replaces 2 m of legs by pi/2 m.
  const Route route({V(0, 0), V(10, 0), V(10, 10)}, 1.0);
  EXPECT_NEAR(route.length(), 18.0 + kPi / 2, 1e-12);
  ASSERT_EQ(route.pieces().size(), 3u);
  EXPECT_NEAR(route.pieces()[1].curvature, 1.0, 1e-12);  // left turn
  const Pose2 arc_mid = route.PoseAt(9.0 + kPi / 4);
  EXPECT_NEAR(arc_mid.x, 9.0 + std::sin(kPi / 4), 1e-12);
  EXPECT_NEAR(arc_mid.y, 1.0 - std::cos(kPi / 4), 1e-12);
  EXPECT_NEAR(arc_mid.theta, kPi / 4, 1e-12);
  const Pose2 end = route.PoseAt(route.length());
  EXPECT_NEAR(end.x, 10.0, 1e-9);
  EXPECT_NEAR(end.y, 10.0, 1e-9);
  EXPECT_NEAR(end.theta, kPi / 2, 1e-12);
}

TEST(Route, ShortLegsShrinkTheRadius) {
  // Legs of 1 m cannot hold a 1 m radius quarter turn (tangent 1 m); the radius becomes 0.5 m.
  const Route route({V(0, 0), V(1, 0), V(1, -1)}, 1.0);
  ASSERT_EQ(route.pieces().size(), 3u);
  EXPECT_NEAR(route.pieces()[1].curvature, -2.0, 1e-12);  // right turn, radius 0.5
  const Pose2 end = route.PoseAt(route.length());
  EXPECT_NEAR(end.x, 1.0, 1e-9);
  EXPECT_NEAR(end.y, -1.0, 1e-9);
}

TEST(Route, PosesAreContinuousAndFollowTheHeading) {
  const Route route({V(0, 0), V(5, 0), V(5, 4), V(1, 6), V(-3, 2)}, 0.8);
  const double ds = 1e-3;
  for (double s = 0.0; s + ds <= route.length(); s += 0.01) {
    const Pose2 a = route.PoseAt(s), b = route.PoseAt(s + ds);
    ASSERT_NEAR(std::sqrt(SquaredDistance(a, b)), ds, 1e-6) << "s = " << s;  // unit speed
    ASSERT_NEAR(NormalizeAngle(std::atan2(b.y - a.y, b.x - a.x) - a.theta), 0.0, 2e-3) << "s = " << s;
    ASSERT_LE(std::fabs(NormalizeAngle(b.theta - a.theta)), ds / 0.8 + 1e-9) << "s = " << s;
  }
}

}  // namespace
}  // namespace slamtune::sim
