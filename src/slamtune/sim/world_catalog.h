// The built-in simulated worlds, selected by name (`slamtune simulate --world NAME`).
//
//   office   (default) an office floor: rooms with doors off a figure-eight of corridors; the
//            route closes the west loop, the east loop, then the outer ring, and enters rooms.
//   hall     a large open hall with pillars, circled twice: odometry drift alone doubles walls.
//   corridor a long, narrow rectangular corridor loop with wall niches, driven 1.75 times.
//
// Worlds with planted front-end failures (fault_worlds.cc; odometry faults of odometry_fault.h
// that slam_karto's default sequential matcher cannot absorb, for checking objectives and tuners
// against the truth):
//   office-slip    office with a 60 deg wheel-slip turn reported at 45 m (a broken wing);
//   office-jump    office with a 1 m odometry jump at 20 m (doubled corridor walls);
//   corridor-long  a corridor loop with a 60 m bare corridor, where matching along the axis
//                  is degenerate, and 5 % too much travel reported along it.
//
// A large building, driven for about 15 minutes, for measuring what a tuner costs on a recording
// of a whole floor (building_world.cc, fault_worlds.cc):
//   building         a 60 x 36 m building: corridors round six furnished blocks, two bands of
//                    rooms, every room different; about 450 m of route with loops revisited.
//   building-broken  the same walls and route with a 50 deg wheel slip reported at 120 m and,
//                    at 245 m, 3 m of travel reported backwards (two breaks).
#pragma once

#include <string>
#include <vector>

#include "slamtune/sim/world.h"

namespace slamtune::sim {

inline constexpr const char* kDefaultWorld = "office";

struct WorldInfo {
  std::string name;
  std::string description;  // one line
};

// All built-in worlds, default first.
std::vector<WorldInfo> ListWorlds();

// The world called `name`; throws InputError naming the known worlds when there is none.
World MakeWorld(const std::string& name);

// The builders behind MakeWorld (one file each).
World MakeOfficeWorld();
World MakeHallWorld();
World MakeCorridorWorld();
World MakeOfficeSlipWorld();
World MakeOfficeJumpWorld();
World MakeCorridorLongWorld();
World MakeBuildingWorld();
World MakeBuildingBrokenWorld();

}  // namespace slamtune::sim
