// The "hall" world: a 32 x 22 m open hall with two rows of pillars, shelves and doorway niches
// along the walls. The route circles the hall twice, 3 m from the walls, then drives along
// two more sides to the corner opposite the start. The laser sees most of the hall from
// anywhere, so scan matching is easy locally, but each long loop lets odometry drift double
// the walls before it closes, and the end point lies far from the start. About 210 m.
#include "slamtune/sim/route_builder.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {

World MakeHallWorld() {
  using V = Eigen::Vector2d;
  WallBuilder walls;
  // Outline, counter-clockwise, so the right side of each wall is outside the hall and niches
  // (negative depth) go outwards.
  walls.WallWithOpenings(V(0, 0), V(32, 0), {{7.0, 1.6, -0.5}, {20.0, 2.4, -0.5}});
  walls.WallWithOpenings(V(32, 0), V(32, 22), {{13.0, 1.6, -0.5}});
  walls.WallWithOpenings(V(32, 22), V(0, 22), {{6.0, 1.6, -0.5}, {22.0, 1.6, -0.5}});
  walls.WallWithOpenings(V(0, 22), V(0, 0), {{8.0, 2.4, -0.5}});
  // Pillars (0.6 m square) in two rows.
  for (double x : {8.0, 16.0, 24.0}) {
    for (double y : {7.5, 14.5}) walls.Box(V(x - 0.3, y - 0.3), V(x + 0.3, y + 0.3));
  }
  // Shelves and crates along the walls (all at least 1.5 m from the route), one crate inside.
  walls.Box(V(11.0, 0.3), V(15.0, 1.0));
  walls.Box(V(23.0, 0.3), V(26.0, 1.2));
  walls.Box(V(31.0, 4.0), V(31.7, 8.0));
  walls.Box(V(30.8, 16.0), V(31.7, 18.5));
  walls.Box(V(14.0, 21.0), V(19.0, 21.7));
  walls.Box(V(0.3, 13.0), V(1.3, 17.0));
  walls.Box(V(0.3, 2.0), V(1.0, 4.5));
  walls.Box(V(18.5, 10.0), V(20.5, 11.5));

  RouteBuilder route(V(5, 3));
  for (int lap = 0; lap < 2; ++lap) route.To(29, 3).To(29, 19).To(3, 19).To(3, 3);
  route.To(29, 3).To(29, 19);

  World world;
  world.walls = walls.Take();
  world.waypoints = route.Take();
  world.turn_radius = 0.8;
  return world;
}

}  // namespace slamtune::sim
