#include "slamtune/slam/testing/corridor_log.h"

#include "slamtune/sim/simulation.h"

namespace slamtune::slam::testing {

io::LaserLog SimulatedCorridorLog() {
  sim::SimulationOptions o;
  o.world = "corridor";
  o.speed_mps = 1.0;
  o.seed = 3;
  return sim::Simulate(o).log;
}

}  // namespace slamtune::slam::testing
