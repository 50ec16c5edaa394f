// `slamtune simulate` as library work: a built-in world simulated (sim/simulation.h) with the
// laser mounting, the planted odometry faults and the world's own faults as asked, written as
// the three files a benchmark dataset has: DIR/NAME.clf, DIR/NAME.relations and DIR/NAME.truth.txt
// (sim/simulation_files.h). The same options and seed give the same files.
#pragma once

#include <string>
#include <vector>

#include "slamtune/sim/simulation.h"
#include "slamtune/sim/simulation_files.h"

namespace slamtune::tune {

struct SimulateOptions {
  sim::SimulationOptions simulation;  // world, seed, laser, odometry noise, relations (laser_offset: below)
  std::string out;                    // output folder (created); required
  std::vector<double> laser_offset;   // X, Y, YAW (m, m, rad) when given; else simulation.laser_offset
  std::vector<std::string> faults;    // KIND,START_M,LENGTH_M[,MAGNITUDE] (sim::ParseOdometryFault), in order
  bool without_world_faults = false;  // leave out the world's planted faults: the healthy twin of a fault world
};

struct SimulateOutcome {
  sim::SimulationSummary summary;
  sim::SimulationFiles files;
  double seconds = 0.0;  // wall time of the simulation and the writing
};

// The simulation options after the laser offset, the faults (after any already in
// simulation.odometry.faults) and without_world_faults. InputError naming the option for a laser
// offset of other than three values or a malformed fault.
sim::SimulationOptions ResolveSimulation(const SimulateOptions& options);

// Simulates and writes the files. InputError without an output folder (before anything else), for
// a bad option (sim::SimulationOptions::Validate) or an unwritable folder.
SimulateOutcome SimulateAndWrite(const SimulateOptions& options);

}  // namespace slamtune::tune
