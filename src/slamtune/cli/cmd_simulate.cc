// `slamtune simulate`: writes a simulated CARMEN log with ground truth (sim/simulation.h; the work:
// tune/simulate_command.h).
//
//   slamtune simulate [--world NAME] [--seed N] --out DIR [laser/odometry options]
//   slamtune simulate --list
//
// Writes DIR/NAME.clf, DIR/NAME.relations and DIR/NAME.truth.txt (sim/simulation_files.h).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "slamtune/cli/command_registry.h"
#include "slamtune/sim/world_catalog.h"
#include "slamtune/tune/simulate_command.h"

namespace slamtune::cli {
namespace {

struct SimulateState {
  tune::SimulateOptions options;
  bool list = false;
};

int ListWorlds() {
  const std::vector<sim::WorldInfo> worlds = sim::ListWorlds();
  int width = 0;
  for (const sim::WorldInfo& world : worlds) width = std::max(width, static_cast<int>(world.name.size()));
  for (const sim::WorldInfo& world : worlds) {
    std::printf("%-*s %s\n", width, world.name.c_str(), world.description.c_str());
  }
  return 0;
}

int Run(const SimulateState& state) {
  if (state.list) return ListWorlds();
  const tune::SimulateOutcome outcome = tune::SimulateAndWrite(state.options);
  const sim::SimulationFiles& files = outcome.files;
  std::printf("%s\n", outcome.summary.Report().c_str());
  std::printf("wrote %s\n      %s\n      %s\n", files.log.c_str(), files.relations.c_str(), files.truth.c_str());
  std::printf("simulated and written in %.2f s\n", outcome.seconds);
  return 0;
}

std::function<int()> Setup(CLI::App& app) {
  auto state = std::make_shared<SimulateState>();
  sim::SimulationOptions& o = state->options.simulation;
  app.add_flag("--list", state->list, "List the built-in worlds and exit");
  app.add_option("--out", state->options.out, "Output folder (created if missing)");
  app.add_option("--world", o.world, "World name (see --list)")->capture_default_str();
  app.add_option("--seed", o.seed, "Random seed; same seed, same files")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--speed", o.speed_mps, "Robot speed along the route (m/s)")->capture_default_str();
  app.add_option("--scan-rate", o.scan_rate_hz, "Laser scans per second (Hz)")->capture_default_str();
  app.add_option("--step-length", o.step_length_m, "Distance between ODOM records (m)")->capture_default_str();
  app.add_option("--start-time", o.start_time_s, "Timestamp of the first record (s)")->capture_default_str();
  app.add_option("--fov", o.laser.fov_deg, "Laser field of view (deg)")->capture_default_str();
  app.add_option("--beams", o.laser.beams, "Readings per scan")->capture_default_str();
  app.add_option("--max-range", o.laser.max_range_m, "Laser max range = no-return value (m)")->capture_default_str();
  app.add_option("--range-noise", o.laser.range_noise_m, "Range noise sigma (m)")->capture_default_str();
  app.add_option("--range-resolution", o.laser.range_resolution_m, "Range quantum (m)")->capture_default_str();
  app.add_flag("--float32-scans", o.laser.float32_values,
               "Beam angles, max range and readings as float32 values, as a ROS LaserScan holds them");
  app.add_option("--laser-offset", state->options.laser_offset,
                 "Laser mounting pose in the robot frame, X,Y,YAW (m, m, rad), e.g. 0.12,-0.04,0.05")
      ->expected(3)
      ->delimiter(',');
  app.add_option("--odom-trans-noise", o.odometry.translation_noise, "Distance noise (m per sqrt(m))")
      ->capture_default_str();
  app.add_option("--odom-rot-noise-per-m", o.odometry.rotation_noise_per_m, "Heading noise per metre (rad/sqrt(m))")
      ->capture_default_str();
  app.add_option("--odom-rot-noise-per-rad", o.odometry.rotation_noise_per_rad,
                 "Heading noise per radian turned (rad/sqrt(rad))")
      ->capture_default_str();
  app.add_option("--odom-trans-bias", o.odometry.translation_scale_bias, "Distance scale error (fraction)")
      ->capture_default_str();
  app.add_option("--odom-rot-bias", o.odometry.rotation_scale_bias, "Rotation scale error (fraction)")
      ->capture_default_str();
  app.add_option("--odom-heading-drift", o.odometry.heading_drift_per_m, "Systematic heading drift (rad/m)")
      ->capture_default_str();
  app.add_option("--fault", state->options.faults,
                 "Plant an odometry fault, KIND,START_M,LENGTH_M[,MAGNITUDE] (repeatable): spin (MAGNITUDE deg "
                 "reported, not turned), jump (MAGNITUDE m reported, not travelled) or reverse (travel reported "
                 "backwards), over LENGTH_M of true travel from START_M along the route");
  app.add_flag("--without-world-faults", state->options.without_world_faults,
               "Leave out the world's planted faults (e.g. corridor-long's odometry scale error): the healthy "
               "twin of a fault world, for the error it would have without its failure");
  app.add_option("--relation-stride", o.relations.stride, "Scans between relation samples")->capture_default_str();
  app.add_option("--relation-gap", o.relations.local_gap_s, "Time between the scans of a local relation (s)")
      ->capture_default_str();
  app.add_option("--revisit-radius", o.relations.revisit_radius_m, "Max distance of a revisit relation (m)")
      ->capture_default_str();
  app.add_option("--revisit-min-gap", o.relations.revisit_min_gap_s, "Min time between revisit scans (s)")
      ->capture_default_str();
  app.footer(
      "Examples:\n"
      "  slamtune simulate --list\n"
      "  slamtune simulate --world hall --seed 2 --out sim/hall\n"
      "  slamtune simulate --world office --fault spin,45,0.1,60 --out sim/slip   # plant a wheel slip\n"
      "  slamtune simulate --world corridor-long --without-world-faults --out sim/twin");
  return [state] { return Run(*state); };
}

const SubcommandRegistrar kSimulate({"simulate",
                                     "Simulate a laser log with odometry drift and ground truth in a built-in world",
                                     25, &Setup});

}  // namespace
}  // namespace slamtune::cli
