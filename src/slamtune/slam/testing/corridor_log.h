// Test fixture: the simulated drive the mapper's whole-run tests share (sim/ corridor world), a
// short log whose run closes a loop with FastMapperParams (engine_state.h).
#pragma once

#include "slamtune/io/laser_log.h"

namespace slamtune::slam::testing {

// The laser log of the corridor world driven at 1 m/s with seed 3.
io::LaserLog SimulatedCorridorLog();

}  // namespace slamtune::slam::testing
