// The "office" world (default): a 28 x 20 m floor.
//
//   y 16..20  four rooms (doors at x = 3.5, 10.5, 17.5, 24.5)
//   y 14..16  north corridor
//   y  6..14  west corridor (x 0..2) | lab (x 2..13, doors south and east) | middle corridor
//             (x 13..15) | two rooms (x 15..26, doors south and north) | east corridor (x 26..28)
//   y  4..6   south corridor
//   y  0..4   four rooms (doors at x = 3.5, 10.5, 17.5, 24.5)
//
// The corridors form a figure eight. The route closes the west loop, then the east loop, then
// drives through the lab and round the outer ring, so loops are nested and every corridor is
// revisited; it enters four rooms on the way. About 230 m.
#include "slamtune/sim/route_builder.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
namespace {

using V = Eigen::Vector2d;
using Opening = WallBuilder::Opening;

constexpr double kOfficeDoor = 1.0;  // doorway width (m)
constexpr double kDoorsX[] = {3.5, 10.5, 17.5, 24.5};

// Furniture of the 7 x 4 m band rooms, different in each room so that rooms do not look alike.
// `x0` is the room's west wall, `y_wall` its corridor wall, `sign` +1 when the room lies north.
void FurnishOfficeBandRoom(WallBuilder& walls, double x0, double y_wall, double sign, int variant) {
  const auto box = [&](double xa, double da, double xb, double db) {
    // (xa, da)-(xb, db): x from the room's west wall, d metres from the corridor wall.
    const double ya = y_wall + sign * da, yb = y_wall + sign * db;
    walls.Box(V(x0 + xa, std::min(ya, yb)), V(x0 + xb, std::max(ya, yb)));
  };
  switch (variant % 4) {
    case 0:
      box(0.2, 3.1, 1.0, 3.8);  // cabinet in the far corner
      box(6.3, 1.3, 6.8, 2.9);  // shelf along the east wall
      break;
    case 1:
      box(0.2, 1.0, 0.7, 3.0);  // shelf along the west wall
      box(5.0, 3.3, 6.8, 3.8);  // desk at the back
      break;
    case 2:
      box(3.0, 3.4, 4.0, 3.8);  // low cabinet at the back, centred
      box(6.2, 3.0, 6.8, 3.8);  // cabinet in the far corner
      box(0.2, 0.2, 0.6, 0.6);  // bin by the door
      break;
    default:
      box(0.2, 2.0, 1.2, 3.8);  // wardrobe
      box(6.3, 0.2, 6.8, 1.2);  // shelf by the door
      break;
  }
}

}  // namespace

World MakeOfficeWorld() {
  WallBuilder walls;
  walls.Box(V(0, 0), V(28, 20));  // outline
  // Room bands: corridor walls with doors, and partitions between rooms.
  std::vector<Opening> band_doors;
  for (double x : kDoorsX) band_doors.push_back({x, kOfficeDoor, 0.0});
  walls.WallWithOpenings(V(0, 4), V(28, 4), band_doors);
  walls.WallWithOpenings(V(0, 16), V(28, 16), band_doors);
  for (double x : {7.0, 14.0, 21.0}) {
    walls.Wall(V(x, 0), V(x, 4));
    walls.Wall(V(x, 16), V(x, 20));
  }
  for (int room = 0; room < 4; ++room) {
    FurnishOfficeBandRoom(walls, 7.0 * room, 4.0, -1.0, room);
    FurnishOfficeBandRoom(walls, 7.0 * room, 16.0, 1.0, room + 2);
  }
  // Lab (x 2..13, y 6..14): doors to the south corridor (x = 7) and the middle corridor (y = 10).
  walls.WallWithOpenings(V(2, 6), V(13, 6), {{5.0, kOfficeDoor, 0.0}});
  walls.WallWithOpenings(V(13, 6), V(13, 14), {{4.0, kOfficeDoor, 0.0}});
  walls.WallWithOpenings(V(13, 14), V(2, 14), {{3.0, 1.2, 0.4}, {8.0, 1.2, 0.4}});  // niches into the lab
  walls.Wall(V(2, 14), V(2, 6));
  walls.Box(V(3.0, 7.0), V(5.0, 8.2));  // desks
  walls.Box(V(9.0, 7.2), V(11.5, 8.4));
  walls.Box(V(3.0, 11.8), V(5.5, 13.0));
  walls.Box(V(9.0, 11.6), V(11.0, 12.8));
  walls.Box(V(4.5, 9.6), V(5.1, 10.2));  // pillar
  // East block (x 15..26, y 6..14): two rooms split at y = 10, doors to the south and north corridors.
  walls.WallWithOpenings(V(15, 6), V(26, 6), {{5.5, kOfficeDoor, 0.0}});
  walls.WallWithOpenings(V(15, 14), V(26, 14), {{5.5, kOfficeDoor, 0.0}});
  walls.WallWithOpenings(V(15, 6), V(15, 14), {{2.0, 1.2, -0.4}, {6.0, 1.2, -0.4}});  // niches off the middle corridor
  walls.Wall(V(26, 6), V(26, 14));
  walls.Wall(V(15, 10), V(26, 10));
  walls.Box(V(15.3, 6.3), V(16.5, 7.0));
  walls.Box(V(24.0, 8.8), V(25.7, 9.7));
  walls.Box(V(15.3, 12.8), V(17.0, 13.7));
  walls.Box(V(24.8, 10.3), V(25.7, 11.5));

  // Route. Corridor centrelines: south y = 5, north y = 15, west x = 1, middle x = 14, east x = 27.
  const V east(1, 0), west(-1, 0), north(0, 1), south(0, -1);
  const auto room = [](RouteBuilder& r, const V& door, const V& inward, const V& along) {
    r.VisitRoom(door, inward, along, 1.0, 1.6, 1.2, 2.6);
  };
  RouteBuilder route(V(2.5, 5));
  room(route, V(10.5, 4), south, east);  // west loop
  route.To(14, 5).To(14, 15);
  room(route, V(3.5, 16), north, west);
  route.To(1, 15).To(1, 5);
  room(route, V(24.5, 4), south, east);  // east loop
  route.To(27, 5).To(27, 15);
  room(route, V(17.5, 16), north, west);
  route.To(14, 15).To(14, 10).To(7, 10).To(7, 5);           // through the lab
  route.To(1, 5).To(1, 15).To(27, 15).To(27, 5).To(16, 5);  // outer ring

  World world;
  world.walls = walls.Take();
  world.waypoints = route.Take();
  world.turn_radius = 0.5;
  return world;
}

}  // namespace slamtune::sim
