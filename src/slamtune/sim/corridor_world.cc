// The "corridor" world: a 50 x 14 m rectangular corridor loop, 2.5 m wide, round a solid block.
// Niches (recessed doorways) every few metres give the otherwise uniform walls some features;
// long straight corridors remain weakly constrained along their axis, the classic hard case
// for scan matching. The route drives the loop 1.75 times. About 200 m.
#include "slamtune/sim/route_builder.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
namespace {

// Niches of `width` every `spacing` metres along a wall of `length`, starting at `first`.
std::vector<WallBuilder::Opening> Niches(double length, double first, double spacing, double width, double depth) {
  std::vector<WallBuilder::Opening> niches;
  for (double at = first; at + width / 2.0 < length - 0.5; at += spacing) niches.push_back({at, width, depth});
  return niches;
}

}  // namespace

World MakeCorridorWorld() {
  using V = Eigen::Vector2d;
  WallBuilder walls;
  // Outer wall, counter-clockwise: left = inside the loop, so niches (negative depth) go outwards.
  walls.WallWithOpenings(V(0, 0), V(50, 0), Niches(50, 4.0, 6.5, 1.2, -0.4));
  walls.WallWithOpenings(V(50, 0), V(50, 14), Niches(14, 5.0, 4.0, 1.2, -0.4));
  walls.WallWithOpenings(V(50, 14), V(0, 14), Niches(50, 7.0, 8.0, 1.2, -0.4));
  walls.WallWithOpenings(V(0, 14), V(0, 0), Niches(14, 7.0, 20.0, 1.6, -0.4));
  // Inner block, clockwise: right = inside the block, so niches (negative depth) go into it.
  walls.WallWithOpenings(V(2.5, 2.5), V(2.5, 11.5), Niches(9, 3.0, 4.0, 1.0, -0.4));
  walls.WallWithOpenings(V(2.5, 11.5), V(47.5, 11.5), Niches(45, 5.5, 11.0, 1.0, -0.4));
  walls.WallWithOpenings(V(47.5, 11.5), V(47.5, 2.5), Niches(9, 4.5, 10.0, 1.0, -0.4));
  walls.WallWithOpenings(V(47.5, 2.5), V(2.5, 2.5), Niches(45, 9.0, 9.0, 1.0, -0.4));

  RouteBuilder route(V(5, 1.25));
  route.To(48.75, 1.25).To(48.75, 12.75).To(1.25, 12.75).To(1.25, 1.25);
  route.To(48.75, 1.25).To(48.75, 12.75).To(20, 12.75);

  World world;
  world.walls = walls.Take();
  world.waypoints = route.Take();
  world.turn_radius = 0.6;
  return world;
}

}  // namespace slamtune::sim
