#include "slamtune/sim/world_catalog.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/sim/route.h"

namespace slamtune::sim {
namespace {

using V = Eigen::Vector2d;

double PointSegmentDistance(const V& p, const Segment& s) {
  const V e = s.b - s.a;
  const double u = std::clamp((p - s.a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (s.a + u * e - p).norm();
}

TEST(WorldCatalog, ListsOfficeFirstThenHallCorridorAndTheFaultWorlds) {
  const auto worlds = ListWorlds();
  ASSERT_EQ(worlds.size(), 6u);
  EXPECT_EQ(worlds[0].name, kDefaultWorld);
  EXPECT_EQ(worlds[0].name, "office");
  EXPECT_EQ(worlds[1].name, "hall");
  EXPECT_EQ(worlds[2].name, "corridor");
  EXPECT_EQ(worlds[3].name, "office-slip");
  EXPECT_EQ(worlds[4].name, "office-jump");
  EXPECT_EQ(worlds[5].name, "corridor-long");
  for (const auto& info : worlds) {
    EXPECT_FALSE(info.description.empty());
    EXPECT_EQ(info.description.find('\n'), std::string::npos);
    const World world = MakeWorld(info.name);
    EXPECT_EQ(world.name, info.name);
    EXPECT_EQ(world.description, info.description);
  }
}

// Plain worlds have no planted faults; each fault world has its fault inside its route, and
// office-slip and office-jump drive exactly the office's walls and route.
TEST(WorldCatalog, FaultWorldsPlantValidFaultsOnTheirRoute) {
  for (const char* plain : {"office", "hall", "corridor"})
    EXPECT_TRUE(MakeWorld(plain).odometry_faults.empty()) << plain;
  const World office = MakeWorld("office");
  for (const char* name : {"office-slip", "office-jump", "corridor-long"}) {
    const World world = MakeWorld(name);
    ASSERT_EQ(world.odometry_faults.size(), 1u) << name;
    const OdometryFault& fault = world.odometry_faults[0];
    EXPECT_NO_THROW(fault.Validate(name));
    const Route route(world.waypoints, world.turn_radius);
    EXPECT_LT(fault.start_m + fault.length_m, route.length() - 50.0) << name << ": room to see its effect";
  }
  for (const char* name : {"office-slip", "office-jump"}) {
    const World world = MakeWorld(name);
    EXPECT_EQ(world.waypoints, office.waypoints) << name;
    EXPECT_EQ(world.walls.size(), office.walls.size()) << name;
  }
  EXPECT_EQ(MakeWorld("office-slip").odometry_faults[0].kind, OdometryFaultKind::kSpin);
  EXPECT_EQ(MakeWorld("office-jump").odometry_faults[0].kind, OdometryFaultKind::kJump);
}

TEST(WorldCatalog, UnknownNameIsAnInputErrorListingTheWorlds) {
  try {
    MakeWorld("moon");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr("'moon'"));
    EXPECT_THAT(e.what(), testing::HasSubstr("office, hall, corridor, office-slip, office-jump, corridor-long"));
  }
}

// The route must stay in free space: never through a wall, never closer than 0.4 m to one
// (the robot's radius), and between 100 and 300 m long.
TEST(WorldCatalog, RoutesStayClearOfWallsAndHaveModestLengths) {
  for (const auto& info : ListWorlds()) {
    const World world = MakeWorld(info.name);
    const Route route(world.waypoints, world.turn_radius);
    EXPECT_GT(route.length(), 100.0) << info.name;
    EXPECT_LT(route.length(), 300.0) << info.name;
    double closest = std::numeric_limits<double>::infinity();
    Pose2 previous = route.PoseAt(0.0);
    for (double s = 0.05; s <= route.length(); s += 0.05) {
      const Pose2 pose = route.PoseAt(s);
      const V p(pose.x, pose.y), q(previous.x, previous.y);
      for (const Segment& wall : world.walls) {
        closest = std::min(closest, PointSegmentDistance(p, wall));
        const auto hit = IntersectRay(q, (p - q).normalized(), wall);
        ASSERT_FALSE(hit && *hit <= (p - q).norm()) << info.name << ": route crosses a wall at s = " << s;
      }
      previous = pose;
    }
    EXPECT_GE(closest, 0.4) << info.name;
  }
}

TEST(WallBuilder, OpeningsLeaveGapsAndNichesCloseThem) {
  WallBuilder builder;
  builder.WallWithOpenings(V(0, 0), V(10, 0), {{2.0, 1.0, 0.0}, {6.0, 2.0, -0.5}});
  const auto walls = builder.Take();
  // [0, 1.5], gap, [2.5, 5], niche (3 walls), [7, 10].
  ASSERT_EQ(walls.size(), 6u);
  EXPECT_TRUE(walls[0].b.isApprox(V(1.5, 0)));
  EXPECT_TRUE(walls[1].a.isApprox(V(2.5, 0)));
  EXPECT_TRUE(walls[2].b.isApprox(V(5, -0.5)));  // negative depth: to the right of +x
  EXPECT_TRUE(walls[3].b.isApprox(V(7, -0.5)));
  EXPECT_TRUE(walls[5].b.isApprox(V(10, 0)));
}

}  // namespace
}  // namespace slamtune::sim
