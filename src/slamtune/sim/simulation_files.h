// Writes a simulation as the three files a benchmark dataset has:
//   DIR/NAME.clf         CARMEN log (io/carmen/carmen_writer.h): header comments, PARAM lines (the
//                        no-return value is PARAM laser_front_laser_max_range), ODOM and FLASER
//   DIR/NAME.relations   Freiburg relations `t1 t2 x y z roll pitch yaw` (io/relations.h)
//   DIR/NAME.truth.txt   `timestamp x y theta`, the true laser pose of every scan (io/trajectory.h)
// NAME is the world's name. Same options and seed give byte-identical files.
#pragma once

#include <string>

#include "slamtune/sim/simulation.h"

namespace slamtune::sim {

struct SimulationFiles {
  std::string log;
  std::string relations;
  std::string truth;
};

// The header comment lines written into the log (what was simulated, and the conventions).
std::vector<std::string> DescribeSimulation(const Simulation& simulation, const SimulationOptions& options);

// Creates `dir` if needed and writes the three files. Throws InputError when `dir` cannot be
// created or a file cannot be written.
SimulationFiles WriteSimulation(const std::string& dir, const Simulation& simulation, const SimulationOptions& options);

}  // namespace slamtune::sim
