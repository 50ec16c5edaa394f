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

TEST(WorldCatalog, ListsOfficeFirstThenHallCorridorTheFaultWorldsAndTheBuilding) {
  const auto worlds = ListWorlds();
  ASSERT_EQ(worlds.size(), 8u);
  EXPECT_EQ(worlds[0].name, kDefaultWorld);
  EXPECT_EQ(worlds[0].name, "office");
  EXPECT_EQ(worlds[1].name, "hall");
  EXPECT_EQ(worlds[2].name, "corridor");
  EXPECT_EQ(worlds[3].name, "office-slip");
  EXPECT_EQ(worlds[4].name, "office-jump");
  EXPECT_EQ(worlds[5].name, "corridor-long");
  EXPECT_EQ(worlds[6].name, "building");
  EXPECT_EQ(worlds[7].name, "building-broken");
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
  for (const char* plain : {"office", "hall", "corridor", "building"})
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

// building-broken drives exactly the building's walls and route, with a wheel slip beyond the
// sequential matcher's +-20 deg before the middle of the route and a reverse stretch of a few
// metres after it, far enough apart and from the end for each to show.
TEST(WorldCatalog, BuildingBrokenPlantsASlipBeforeTheMiddleAndAReverseStretchAfterIt) {
  const World building = MakeWorld("building");
  const World broken = MakeWorld("building-broken");
  EXPECT_EQ(broken.waypoints, building.waypoints);
  ASSERT_EQ(broken.walls.size(), building.walls.size());
  for (std::size_t i = 0; i < building.walls.size(); ++i) {
    EXPECT_EQ(broken.walls[i].a, building.walls[i].a);
    EXPECT_EQ(broken.walls[i].b, building.walls[i].b);
  }
  EXPECT_EQ(broken.turn_radius, building.turn_radius);
  const double length = Route(building.waypoints, building.turn_radius).length();
  ASSERT_EQ(broken.odometry_faults.size(), 2u);
  const OdometryFault& slip = broken.odometry_faults[0];
  const OdometryFault& reverse = broken.odometry_faults[1];
  EXPECT_NO_THROW(slip.Validate("slip"));
  EXPECT_NO_THROW(reverse.Validate("reverse"));
  EXPECT_EQ(slip.kind, OdometryFaultKind::kSpin);
  EXPECT_GT(std::fabs(slip.magnitude), 0.349 + 0.3) << "well beyond slam_karto's coarse_search_angle_offset";
  EXPECT_LE(slip.length_m, 0.2);
  EXPECT_LT(slip.start_m + slip.length_m, length / 2.0);
  EXPECT_EQ(reverse.kind, OdometryFaultKind::kReverse);
  EXPECT_GE(reverse.length_m, 1.0);
  EXPECT_LE(reverse.length_m, 5.0);
  EXPECT_GT(reverse.start_m, slip.start_m + 50.0);
  EXPECT_LT(reverse.start_m + reverse.length_m, length - 50.0);
}

TEST(WorldCatalog, UnknownNameIsAnInputErrorListingTheWorlds) {
  try {
    MakeWorld("moon");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("'moon'"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("office, hall, corridor, office-slip, office-jump, corridor-long, "
                                               "building, building-broken"));
  }
}

// The route must stay in free space: never through a wall, never closer than 0.4 m to one
// (the robot's radius), and between 100 and 300 m long; the building's between 400 m (15 minutes
// at 0.5 m/s) and 480 m (some 4800 scans at 5 Hz).
TEST(WorldCatalog, RoutesStayClearOfWallsAndHaveModestLengths) {
  for (const auto& info : ListWorlds()) {
    const World world = MakeWorld(info.name);
    const Route route(world.waypoints, world.turn_radius);
    const bool building = info.name.starts_with("building");
    EXPECT_GT(route.length(), building ? 400.0 : 100.0) << info.name;
    EXPECT_LT(route.length(), building ? 480.0 : 300.0) << info.name;
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
