#include "slamtune/tune/simulate_command.h"

#include <chrono>

#include "slamtune/common/error.h"

namespace slamtune::tune {

sim::SimulationOptions ResolveSimulation(const SimulateOptions& options) {
  sim::SimulationOptions resolved = options.simulation;
  if (!options.laser_offset.empty()) {
    if (options.laser_offset.size() != 3) {
      throw InputError("--laser-offset: " + std::to_string(options.laser_offset.size()) +
                       " values; give X,Y,YAW (m, m, rad)");
    }
    resolved.laser_offset = Pose2{options.laser_offset[0], options.laser_offset[1], options.laser_offset[2]};
  }
  resolved.plant_world_faults = !options.without_world_faults;
  for (const std::string& fault : options.faults) resolved.odometry.faults.push_back(sim::ParseOdometryFault(fault));
  return resolved;
}

SimulateOutcome SimulateAndWrite(const SimulateOptions& options) {
  if (options.out.empty()) {
    throw InputError("--out: required (the folder to write NAME.clf, NAME.relations, NAME.truth.txt)");
  }
  const sim::SimulationOptions resolved = ResolveSimulation(options);
  const auto start = std::chrono::steady_clock::now();
  const sim::Simulation simulation = sim::Simulate(resolved);
  SimulateOutcome out;
  out.files = sim::WriteSimulation(options.out, simulation, resolved);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.summary = simulation.summary;
  return out;
}

}  // namespace slamtune::tune
