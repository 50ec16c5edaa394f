#include "slamtune/sim/world_catalog.h"

#include "slamtune/common/error.h"

namespace slamtune::sim {
namespace {

struct Entry {
  const char* name;
  const char* description;
  World (*make)();
};

constexpr Entry kWorlds[] = {
    {"office",
     "28 x 20 m office floor: rooms with doors off a figure-eight of corridors; west loop, east loop, outer ring, "
     "4 room visits (default)",
     &MakeOfficeWorld},
    {"hall",
     "32 x 22 m open hall with pillars and shelves, circled twice along the walls, ending at the far corner "
     "(drift doubles walls)",
     &MakeHallWorld},
    {"corridor", "50 x 14 m rectangular corridor loop, 2.5 m wide, with wall niches, driven 1.75 times",
     &MakeCorridorWorld},
    {"office-slip",
     "office with a wheel slip at 45 m: odometry reports a 60 deg turn within 0.1 m that did not "
     "happen (beyond the +-20 deg sequential search)",
     &MakeOfficeSlipWorld},
    {"office-jump",
     "office with a 1 m odometry jump at 20 m, leaving the first room (beyond the +-0.15 m "
     "sequential window)",
     &MakeOfficeJumpWorld},
    {"corridor-long",
     "64 x 12 m corridor loop whose south corridor has 32 m of bare walls; odometry reports 5 % "
     "too much travel along them",
     &MakeCorridorLongWorld},
    {"building",
     "60 x 36 m building: four corridors round six furnished blocks between two bands of rooms, "
     "every room different; 450 m (15 min), loops revisited",
     &MakeBuildingWorld},
    {"building-broken",
     "building with a 50 deg wheel slip reported within 0.1 m at 120 m and 3 m of travel "
     "reported backwards at 245 m (beyond the sequential search)",
     &MakeBuildingBrokenWorld},
};

}  // namespace

std::vector<WorldInfo> ListWorlds() {
  std::vector<WorldInfo> worlds;
  for (const Entry& entry : kWorlds) worlds.push_back({entry.name, entry.description});
  return worlds;
}

World MakeWorld(const std::string& name) {
  std::string known;
  for (const Entry& entry : kWorlds) {
    if (name == entry.name) {
      World world = entry.make();
      world.name = entry.name;
      world.description = entry.description;
      return world;
    }
    known += known.empty() ? entry.name : std::string(", ") + entry.name;
  }
  throw InputError("world: unknown world '" + name + "' (known: " + known + ")");
}

}  // namespace slamtune::sim
