#include "slamtune/sim/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/karto_math.h"
#include "slamtune/sim/random.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
namespace {

using V = Eigen::Vector2d;

std::vector<Segment> Square(double size) {
  return {{V(0, 0), V(size, 0)}, {V(size, 0), V(size, size)}, {V(size, size), V(0, size)}, {V(0, size), V(0, 0)}};
}

// Reference: test every segment.
std::optional<double> CastBruteForce(const std::vector<Segment>& segments, const V& origin, double angle,
                                     double max_range) {
  const V direction(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : segments) {
    if (auto t = IntersectRay(origin, direction, s); t && *t < best) best = *t;
  }
  if (best <= max_range) return best;
  return std::nullopt;
}

TEST(IntersectRay, HitsMissesAndParallel) {
  const Segment wall{V(2, -1), V(2, 1)};
  EXPECT_DOUBLE_EQ(*IntersectRay(V(0, 0), V(1, 0), wall), 2.0);
  EXPECT_FALSE(IntersectRay(V(0, 0), V(-1, 0), wall));           // behind the ray
  EXPECT_FALSE(IntersectRay(V(0, 2), V(1, 0), wall));            // passes above
  EXPECT_FALSE(IntersectRay(V(2, -5), V(0, 1), wall));           // collinear: edge-on
  EXPECT_DOUBLE_EQ(*IntersectRay(V(0, 1), V(1, 0), wall), 2.0);  // endpoint counts
}

TEST(RayCaster, HitsKnownWallsAtKnownRanges) {
  const RayCaster caster(Square(10.0), 1.0);
  const V origin(3, 4);
  EXPECT_NEAR(*caster.Cast(origin, 0.0, 30.0), 7.0, 1e-12);
  EXPECT_NEAR(*caster.Cast(origin, kPi / 2, 30.0), 6.0, 1e-12);
  EXPECT_NEAR(*caster.Cast(origin, kPi, 30.0), 3.0, 1e-12);
  EXPECT_NEAR(*caster.Cast(origin, -kPi / 2, 30.0), 4.0, 1e-12);
  // 45 degrees from (3, 4): reaches y = 10 after 6 m in x and y.
  EXPECT_NEAR(*caster.Cast(origin, kPi / 4, 30.0), 6.0 * std::sqrt(2.0), 1e-12);
  // A wall beyond max range is not seen.
  EXPECT_FALSE(caster.Cast(origin, 0.0, 6.99));
  EXPECT_NEAR(*caster.Cast(origin, 0.0, 7.0), 7.0, 1e-12);
}

TEST(RayCaster, EmptyWorldAndOpenSideGiveNoHit) {
  EXPECT_FALSE(RayCaster({}).Cast(V(0, 0), 0.0, 100.0));
  const RayCaster caster({{V(5, -1), V(5, 1)}}, 0.5);
  EXPECT_NEAR(*caster.Cast(V(0, 0), 0.0, 100.0), 5.0, 1e-12);
  EXPECT_FALSE(caster.Cast(V(0, 0), kPi, 100.0));
  EXPECT_FALSE(caster.Cast(V(0, 0), 0.5, 100.0));
  // Origin outside the grid, looking at it.
  EXPECT_NEAR(*caster.Cast(V(-20, 0), 0.0, 100.0), 25.0, 1e-12);
}

TEST(RayCaster, NearestOfSeveralWallsAndAPillar) {
  std::vector<Segment> walls = Square(20.0);
  for (const Segment& s :
       std::vector<Segment>{{V(8, 9), V(9, 9)}, {V(9, 9), V(9, 10)}, {V(9, 10), V(8, 10)}, {V(8, 10), V(8, 9)}}) {
    walls.push_back(s);
  }
  const RayCaster caster(walls, 1.0);
  EXPECT_NEAR(*caster.Cast(V(2, 9.5), 0.0, 30.0), 6.0, 1e-12);   // pillar's west face at x = 8
  EXPECT_NEAR(*caster.Cast(V(2, 11), 0.0, 30.0), 18.0, 1e-12);   // above the pillar: outer wall
  EXPECT_NEAR(*caster.Cast(V(15, 9.5), kPi, 30.0), 6.0, 1e-12);  // from the east: face at x = 9
}

TEST(RayCaster, GridAgreesWithBruteForceInEveryWorld) {
  for (const WorldInfo& info : ListWorlds()) {
    const World world = MakeWorld(info.name);
    for (double cell : {0.37, 1.0, 2.5}) {
      const RayCaster caster(world.walls, cell);
      Random random(99);
      for (int i = 0; i < 3000; ++i) {
        const V origin(-2 + 55 * random.Uniform(), -2 + 28 * random.Uniform());
        const double angle = kTwoPi * random.Uniform();
        const auto grid = caster.Cast(origin, angle, 30.0);
        const auto brute = CastBruteForce(world.walls, origin, angle, 30.0);
        ASSERT_EQ(grid.has_value(), brute.has_value())
            << info.name << " ray " << i << " cell " << cell << " from " << origin.transpose() << " angle " << angle
            << " brute " << brute.value_or(-1);
        if (grid) {
          ASSERT_NEAR(*grid, *brute, 1e-9) << info.name << " ray " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace slamtune::sim
