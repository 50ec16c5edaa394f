// Worlds with planted front-end failures: the built-in worlds' walls and routes with odometry
// faults (odometry_fault.h) that break Karto's sequential scan matching at slam_karto's
// defaults, the way real logs break, so that objectives and tuners can be checked against the
// true trajectory.
//
//   office-slip    office, with a wheel slip 45 m along the route (entering the north-west room):
//                  the odometry reports a 60 deg turn within 0.1 m that did not happen. The
//                  sequential matcher searches +-20 deg (coarse_search_angle_offset 0.349 rad)
//                  and cannot take the turn back: the rest of the map is rotated, a broken wing.
//   office-jump    office, with a 1 m translation jump 20 m along the route (leaving the first
//                  room): more than six times the +-0.15 m sequential window; the scans after
//                  it are placed too far on and the middle corridor's walls come out doubled.
//   corridor-long  a 64 x 12 m corridor loop whose south corridor has bare walls from x = 16 m to
//                  48 m: along them scan matching is degenerate and the pose follows the odometry,
//                  which there reports 1.5 m more travel than driven (a scale error of 5 % over
//                  30 m); the pillars at both ends show the map doubled. Without the fault
//                  (simulate --without-world-faults) the same corridor maps within a few cm.
//   building-broken  the building (building_world.cc), a 15-minute drive, with two failures: a
//                  wheel slip 120 m along the route (driving east along the south corridor, before
//                  the middle of the route), where the odometry reports a 50 deg turn within 0.1 m,
//                  beyond the +-20 deg sequential search; and, 245 m along, 3 m of travel reported
//                  backwards (an encoder's sign error) while the robot enters a room off the north
//                  corridor: each node is guessed about 1 m behind, beyond the +-0.15 m window, and
//                  the rest of the route is drawn some 5 m back. Both show as breaks in the front
//                  end's evidence; without them (simulate --without-world-faults) the log is the
//                  building's.
#include "slamtune/common/karto_math.h"
#include "slamtune/sim/route_builder.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
World MakeOfficeSlipWorld() {
  World world = MakeOfficeWorld();
  world.odometry_faults = {OdometryFault{OdometryFaultKind::kSpin, 45.0, 0.1, DegToRad(60.0)}};
  return world;
}

World MakeOfficeJumpWorld() {
  World world = MakeOfficeWorld();
  world.odometry_faults = {OdometryFault{OdometryFaultKind::kJump, 20.0, 0.1, 1.0}};
  return world;
}

World MakeCorridorLongWorld() {
  using V = Eigen::Vector2d;
  WallBuilder walls;
  // Outer wall, counter-clockwise; walls have niches every few metres (negative depth: away from
  // the corridor), except the south corridor's two walls (y = 0 and the block's face at y = 2.5):
  // pillars jut 0.4 m into it near both ends, and between x = 16 and x = 48 m they are bare.
  walls.WallWithOpenings(V(0, 0), V(64, 0), {{6.0, 1.2, 0.4}, {12.0, 1.2, 0.4}, {52.0, 1.2, 0.4}, {58.0, 1.2, 0.4}});
  walls.WallWithOpenings(V(64, 0), V(64, 12), {{4.0, 1.2, -0.4}, {8.5, 1.2, -0.4}});
  std::vector<WallBuilder::Opening> north;
  for (double at = 5.0; at < 62.0; at += 7.0) north.push_back({at, 1.2, -0.4});
  walls.WallWithOpenings(V(64, 12), V(0, 12), north);
  walls.WallWithOpenings(V(0, 12), V(0, 0), {{5.0, 1.6, -0.4}});
  // Inner block, clockwise.
  walls.WallWithOpenings(V(2.5, 2.5), V(2.5, 9.5), {{3.5, 1.0, -0.4}});
  std::vector<WallBuilder::Opening> block_north;
  for (double at = 6.0; at < 58.0; at += 9.0) block_north.push_back({at, 1.0, -0.4});
  walls.WallWithOpenings(V(2.5, 9.5), V(61.5, 9.5), block_north);
  walls.WallWithOpenings(V(61.5, 9.5), V(61.5, 2.5), {{3.0, 1.0, -0.4}});
  walls.WallWithOpenings(V(61.5, 2.5), V(2.5, 2.5), {{6.5, 1.0, 0.4}, {50.5, 1.0, 0.4}});

  RouteBuilder route(V(4, 1.25));
  route.To(62.75, 1.25).To(62.75, 10.75).To(1.25, 10.75).To(1.25, 1.25);
  route.To(62.75, 1.25).To(62.75, 8);

  World world;
  world.walls = walls.Take();
  world.waypoints = route.Take();
  world.turn_radius = 0.6;
  world.odometry_faults = {OdometryFault{OdometryFaultKind::kJump, 13.0, 30.0, 1.5}};
  return world;
}

World MakeBuildingBrokenWorld() {
  World world = MakeBuildingWorld();
  world.odometry_faults = {OdometryFault{OdometryFaultKind::kSpin, 120.0, 0.1, DegToRad(50.0)},
                           OdometryFault{OdometryFaultKind::kReverse, 245.0, 3.0, 0.0}};
  return world;
}

}  // namespace slamtune::sim
