// The "building" world: a 60 x 36 m office building, about four times the office floor, driven for
// about 15 minutes at the simulator's defaults (0.5 m/s, 5 scans/s: some 4500 scans), the size of
// a real recording of a whole floor, on which a tuner's cost can be measured.
//
//   y 30..36  eight rooms of different widths (doors off the north corridor)
//   y 28..30  north corridor
//   y 19..28  library (x 2..19) | lecture hall with pillars (x 21..39) | two labs (x 41..58)
//   y 17..19  central corridor
//   y  8..17  workshop (x 2..19) | meeting room and kitchen (x 21..39) | open-plan office (x 41..58)
//   y  6..8   south corridor
//   y  0..6   eight rooms of different widths (doors off the south corridor)
//   west, middle-west, middle-east and east corridors at x 0..2, 19..21, 39..41, 58..60 (y 6..30)
//
// Rooms differ in width, doorway and furniture, so that no two look alike, and the walls facing the
// corridors have niches every few metres, so that no corridor is bare. The route closes the
// south-west loop (south, middle-west, central and west corridors), drives the south corridor again
// to the middle-east one, closes the loop through the north and middle-west corridors, crosses the
// building along the central corridor and comes back along the east and north corridors, the north
// one a second time, to the west corridor: loops close on the south, central and north corridors.
// It enters eleven rooms on the way. About 450 m.
#include "slamtune/sim/route_builder.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
namespace {

using V = Eigen::Vector2d;
using Opening = WallBuilder::Opening;

constexpr double kBuildingDoor = 1.2;  // doorway width (m)

// A room's frame: the doorway's centre `door` on the wall the room is entered through, `inward`
// into the room and `along` the wall. Box(u0, d0, u1, d1) is the rectangle u0..u1 along the wall
// from the doorway's axis and d0..d1 deep from the wall.
struct RoomFrame {
  V door, inward, along;
  void Box(WallBuilder& walls, double u0, double d0, double u1, double d1) const {
    const V a = door + u0 * along + d0 * inward, b = door + u1 * along + d1 * inward;
    walls.Box(a.cwiseMin(b), a.cwiseMax(b));
  }
};

// Furniture of the 6 m deep band rooms, one of five arrangements (0-4), none in the room's middle, where
// the route goes round. `left` and `right` are the room's extent either side of the doorway (m).
void FurnishBuildingBandRoom(WallBuilder& walls, const RoomFrame& room, double left, double right, int variant) {
  const double l = -left + 0.2, r = right - 0.2;  // 0.2 m off the side walls
  switch (variant) {
    case 0:
      room.Box(walls, l, 4.8, l + 1.4, 5.8);  // cabinet in a far corner
      room.Box(walls, r - 0.6, 1.2, r, 3.6);  // shelf along the side wall
      break;
    case 1:
      room.Box(walls, l, 1.0, l + 0.5, 4.0);  // shelf along the other side wall
      room.Box(walls, r - 2.4, 5.0, r, 5.8);  // desk at the back
      room.Box(walls, 0.0, 5.2, 0.8, 5.8);    // low cabinet behind the route
      break;
    case 2:
      room.Box(walls, -0.8, 5.1, 0.8, 5.8);   // sideboard at the back, centred
      room.Box(walls, r - 0.8, 4.6, r, 5.8);  // cabinet in a far corner
      room.Box(walls, l, 0.2, l + 0.4, 0.6);  // bin by the door
      break;
    case 3:
      room.Box(walls, l, 2.0, l + 0.8, 4.2);        // wardrobe
      room.Box(walls, r - 0.5, 0.2, r, 1.2);        // shelf by the door
      room.Box(walls, r - 1.8, 5.2, r - 0.6, 5.8);  // crate at the back
      break;
    default:
      room.Box(walls, l, 4.9, l + 2.2, 5.8);  // corner desk, L-shaped
      room.Box(walls, l, 3.0, l + 0.7, 4.9);
      room.Box(walls, r - 0.4, 2.0, r, 2.6);        // pillar-like column by the side wall
      room.Box(walls, r - 1.6, 5.3, r - 0.9, 5.8);  // printer
      break;
  }
}

// A band of rooms between y_wall (the corridor wall) and y_outer (the outline), with partitions
// at `partitions` (x), each room's doorway at `doors` (x, one per room, west to east) and its
// furniture arrangement in `variants`: rooms of the same width and doorway get different ones.
void BandOfRooms(WallBuilder& walls, double y_wall, double y_outer, const std::vector<double>& partitions,
                 const std::vector<double>& doors, const std::vector<int>& variants) {
  std::vector<Opening> openings;
  for (double x : doors) openings.push_back({x, kBuildingDoor, 0.0});
  walls.WallWithOpenings(V(0, y_wall), V(60, y_wall), openings);
  const double sign = y_outer > y_wall ? 1.0 : -1.0;
  for (double x : partitions) walls.Wall(V(x, y_wall), V(x, y_outer));
  std::vector<double> edges = {0.0};
  edges.insert(edges.end(), partitions.begin(), partitions.end());
  edges.push_back(60.0);
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const RoomFrame room{V(doors[i], y_wall), V(0, sign), V(1, 0)};
    FurnishBuildingBandRoom(walls, room, doors[i] - edges[i], edges[i + 1] - doors[i], variants[i]);
  }
}

// Niches 1.2 m wide and 0.4 m deep every `spacing` metres along a wall from a to b (into the
// block, to the wall's `side`: +1 left of a -> b, -1 right), skipping `doors` (positions along
// the wall, each an open doorway).
void BlockWall(WallBuilder& walls, const V& a, const V& b, double side, double first, double spacing,
               const std::vector<double>& doors) {
  const double length = (b - a).norm();
  std::vector<Opening> openings;
  std::size_t next_door = 0;
  for (double at = first; at + 0.6 < length; at += spacing) {
    while (next_door < doors.size() && doors[next_door] + kBuildingDoor / 2 < at - 0.6 - 0.3) {
      openings.push_back({doors[next_door++], kBuildingDoor, 0.0});
    }
    if (next_door < doors.size() && std::abs(doors[next_door] - at) < kBuildingDoor / 2 + 0.6 + 0.3) continue;
    openings.push_back({at, 1.2, 0.4 * side});
  }
  while (next_door < doors.size()) openings.push_back({doors[next_door++], kBuildingDoor, 0.0});
  walls.WallWithOpenings(a, b, openings);
}

// The six blocks between the corridors, each wall facing a corridor with niches into the block
// (walls run counter-clockwise round each block, so the block is on their left: side +1).
struct BuildingBlock {
  double x0, y0, x1, y1;
  // Doors are positions along each wall from its counter-clockwise start.
  std::vector<double> south_doors, east_doors, north_doors, west_doors;
  // m along the south wall to its first niche; along the east, north and west walls 1, 2 and 0.5 m more.
  double first;
};

const std::vector<BuildingBlock>& BuildingBlocks() {
  static const std::vector<BuildingBlock> blocks = {
      {2, 8, 19, 17, {}, {}, {}, {4.5}, 2.0},              // workshop, door west at y = 12.5
      {21, 8, 39, 17, {13.5}, {}, {4.0, 13.5}, {}, 2.5},   // meeting room + kitchen
      {41, 8, 58, 17, {}, {}, {}, {4.5}, 3.0},             // open-plan office, door west at y = 12.5
      {2, 19, 19, 28, {8.5}, {}, {}, {}, 2.2},             // library, door south at x = 10.5
      {21, 19, 39, 28, {13.0}, {}, {}, {}, 2.8},           // lecture hall, door south at x = 34
      {41, 19, 58, 28, {}, {}, {8.0}, {2.25, 6.75}, 3.3},  // two labs, doors west at y = 21.25, 25.75
  };
  return blocks;
}

void BuildingBlockWalls(WallBuilder& walls, const BuildingBlock& b) {
  BlockWall(walls, V(b.x0, b.y0), V(b.x1, b.y0), 1.0, b.first, 5.5, b.south_doors);
  BlockWall(walls, V(b.x1, b.y0), V(b.x1, b.y1), 1.0, b.first + 1.0, 5.5, b.east_doors);
  BlockWall(walls, V(b.x1, b.y1), V(b.x0, b.y1), 1.0, b.first + 2.0, 5.5, b.north_doors);
  BlockWall(walls, V(b.x0, b.y1), V(b.x0, b.y0), 1.0, b.first + 0.5, 5.5, b.west_doors);
}

// The furniture of the blocks south of the central corridor.
void FurnishBuildingSouthBlocks(WallBuilder& walls) {
  // Workshop (x 2..19, y 8..17): benches, shelves, a pillar.
  walls.Box(V(2.3, 8.8), V(4.0, 9.6));
  walls.Box(V(8.5, 9.8), V(12.0, 11.0));
  walls.Box(V(8.5, 13.2), V(12.0, 14.4));
  walls.Box(V(14.0, 9.4), V(18.0, 10.2));
  walls.Box(V(15.0, 12.5), V(15.8, 13.3));
  walls.Box(V(13.5, 15.6), V(18.0, 16.4));
  // Meeting room (x 21..30) and kitchen (x 30..39), an inner door between them at y = 12.5.
  walls.WallWithOpenings(V(30, 8), V(30, 17), {{4.5, 1.0, 0.0}});
  walls.Box(V(23.5, 9.6), V(27.5, 10.8));  // meeting table
  walls.Box(V(21.6, 14.8), V(22.6, 16.2));
  walls.Box(V(28.6, 9.0), V(29.4, 11.0));
  walls.Box(V(37.6, 9.8), V(38.4, 15.6));   // kitchen counter
  walls.Box(V(33.0, 11.8), V(35.0, 13.2));  // kitchen table
  // Open-plan office (x 41..58, y 8..17): four desk clusters, a printer corner, a cabinet.
  for (double x : {48.0, 52.5}) {
    walls.Box(V(x, 9.2), V(x + 2.0, 11.0));
    walls.Box(V(x, 13.0), V(x + 2.0, 14.8));
  }
  walls.Box(V(55.6, 9.0), V(57.4, 10.6));
  walls.Box(V(41.6, 15.4), V(43.4, 16.4));
}

// The furniture of the blocks north of the central corridor.
void FurnishBuildingNorthBlocks(WallBuilder& walls) {
  // Library (x 2..19, y 19..28): rows of shelves either side of the reading area.
  for (double y : {21.0, 23.0, 25.0}) walls.Box(V(3.0, y), V(6.5, y + 0.5));
  for (double y : {21.2, 23.6}) walls.Box(V(14.5, y), V(18.0, y + 0.5));
  walls.Box(V(8.0, 26.2), V(13.0, 26.8));
  walls.Box(V(15.0, 26.6), V(17.5, 27.4));
  // Lecture hall (x 21..39, y 19..28): two rows of pillars, a stage, a lectern.
  for (double x : {24.0, 28.0}) {
    for (double y : {22.0, 25.0}) walls.Box(V(x, y), V(x + 0.6, y + 0.6));
  }
  walls.Box(V(22.0, 26.6), V(30.0, 27.4));
  walls.Box(V(37.4, 26.4), V(38.4, 27.4));
  walls.Box(V(31.0, 26.8), V(33.0, 27.4));
  // Two labs (x 41..58), split at y = 23.5 with a door at x = 52.
  walls.WallWithOpenings(V(41, 23.5), V(58, 23.5), {{11.0, 1.0, 0.0}});
  walls.Box(V(49.0, 19.3), V(57.6, 20.0));
  walls.Box(V(53.5, 21.2), V(55.0, 23.0));
  walls.Box(V(48.0, 22.2), V(49.2, 23.0));
  walls.Box(V(43.0, 26.8), V(46.0, 27.6));
  walls.Box(V(50.0, 24.6), V(51.0, 25.6));
  walls.Box(V(56.4, 24.0), V(57.6, 27.6));
}

// The route. Corridor centrelines: south y = 7, central y = 18, north y = 29; west x = 1,
// middle-west x = 20, middle-east x = 40, east x = 59.
std::vector<V> BuildingRoute() {
  const V east(1, 0), west(-1, 0), north(0, 1), south(0, -1);
  const auto band_room = [](RouteBuilder& r, const V& door, const V& inward, const V& along) {
    r.VisitRoom(door, inward, along, 1.0, 1.8, 1.5, 4.2);
  };
  const auto block_room = [](RouteBuilder& r, const V& door, const V& inward, const V& along, double half_width) {
    r.VisitRoom(door, inward, along, 1.0, half_width, 1.5, 5.0);
  };
  RouteBuilder route(V(3, 7));
  band_room(route, V(11.5, 6), south, east);  // south-west loop
  route.To(20, 7).To(20, 18);
  block_room(route, V(10.5, 19), north, west, 2.0);  // library
  route.To(1, 18);
  block_room(route, V(2, 12.5), east, south, 2.0);  // workshop
  route.To(1, 7);
  band_room(route, V(34, 6), south, east);  // south corridor again, on to the middle-east corridor
  route.To(40, 7);
  block_room(route, V(41, 12.5), east, north, 2.0);   // open-plan office
  block_room(route, V(41, 21.25), east, north, 1.2);  // south lab
  route.To(40, 29);
  band_room(route, V(26, 30), north, west);  // north corridor, back down the middle-west one
  route.To(20, 29).To(20, 18);
  block_room(route, V(25.5, 17), south, east, 2.0);  // meeting room
  block_room(route, V(34, 19), north, east, 2.0);    // lecture hall
  route.To(59, 18).To(59, 29);                       // outer ring
  band_room(route, V(49, 30), north, west);
  band_room(route, V(11, 30), north, west);
  route.To(1, 29).To(1, 19);
  return route.Take();
}

}  // namespace

World MakeBuildingWorld() {
  WallBuilder walls;
  walls.Box(V(0, 0), V(60, 36));  // outline
  BandOfRooms(walls, 6.0, 0.0, {8, 15, 23, 30, 38, 45, 52}, {4.5, 11.5, 19.0, 26.5, 34.0, 41.5, 48.5, 56.0},
              {0, 1, 2, 3, 4, 0, 2, 1});
  BandOfRooms(walls, 30.0, 36.0, {7, 15, 22, 30, 37, 45, 53}, {3.5, 11.0, 18.5, 26.0, 33.5, 41.0, 49.0, 56.5},
              {3, 4, 0, 1, 2, 3, 0, 1});
  for (const BuildingBlock& block : BuildingBlocks()) BuildingBlockWalls(walls, block);
  FurnishBuildingSouthBlocks(walls);
  FurnishBuildingNorthBlocks(walls);

  World world;
  world.walls = walls.Take();
  world.waypoints = BuildingRoute();
  world.turn_radius = 0.5;
  return world;
}

}  // namespace slamtune::sim
