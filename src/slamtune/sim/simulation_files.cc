#include "slamtune/sim/simulation_files.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <system_error>

#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_writer.h"

namespace slamtune::sim {
namespace {

bool HasOffset(const SimulationOptions& options) {
  const Pose2& o = options.laser_offset;
  return o.x != 0.0 || o.y != 0.0 || o.theta != 0.0;
}

std::string LaserPoseComment(const Simulation& simulation, const SimulationOptions& options) {
  const bool flaser = simulation.log.scans.empty() || simulation.log.scans.front().kind == io::RecordKind::kFlaser;
  if (!HasOffset(options)) {
    return flaser ? "FLASER x y theta = odom_x odom_y odom_theta = odometric laser pose (laser at the robot origin)"
                  : "ROBOTLASER1 laser pose = robot pose = odometric laser pose (laser at the robot origin)";
  }
  const Pose2& o = options.laser_offset;
  return fmt::format(
      "{}: laser pose = robot pose (+) mounting offset ({}, {}, {}) (m, m, rad), the PARAMs "
      "robot_frontlaser_offset, _side_offset, _angular_offset",
      flaser ? "FLASER" : "ROBOTLASER1", o.x, o.y, o.theta);
}

// Digits after the point that print multiples of `resolution` exactly (9 at most).
int RangeDecimals(double resolution) {
  for (int d = 3; d < 9; ++d) {
    const double scaled = resolution * std::pow(10.0, d);
    if (std::fabs(scaled - std::round(scaled)) < 1e-9) return d;
  }
  return 9;
}

}  // namespace

std::vector<std::string> DescribeSimulation(const Simulation& simulation, const SimulationOptions& options) {
  const LaserOptions& laser = options.laser;
  const OdometryNoiseOptions& odo = options.odometry;
  std::vector<std::string> lines = {
      fmt::format("simulated by slamtune: world {} (seed {}): {}", simulation.world.name, options.seed,
                  simulation.world.description),
      fmt::format("route {:.2f} m at {} m/s; laser {} Hz; ODOM every {} m", simulation.summary.path_length_m,
                  options.speed_mps, options.scan_rate_hz, options.step_length_m),
      fmt::format("laser: {} beams over {} deg, beam i at ({} + i * {}) deg from the heading; max range {} m; "
                  "range noise sigma {} m; readings in steps of {} m",
                  laser.beams, laser.fov_deg, -laser.fov_deg / 2.0, laser.fov_deg / (laser.beams - 1),
                  laser.max_range_m, laser.range_noise_m, laser.range_resolution_m),
      fmt::format("no return: the reading equals the max range, given by PARAM {}", kMaxRangeParam),
      fmt::format("odometry noise: translation {} m/sqrt(m), rotation {} rad/sqrt(m) + {} rad/sqrt(rad); bias: "
                  "distance x{}, rotation x{}, heading drift {} rad/m",
                  odo.translation_noise, odo.rotation_noise_per_m, odo.rotation_noise_per_rad,
                  1.0 + odo.translation_scale_bias, 1.0 + odo.rotation_scale_bias, odo.heading_drift_per_m),
      LaserPoseComment(simulation, options),
      fmt::format("ground truth: {0}.truth.txt (true laser pose per scan), {0}.relations (Freiburg format)",
                  simulation.world.name),
  };
  // Only a log with planted faults says so, so the plain worlds' logs keep their header.
  const std::vector<OdometryFault>& faults = simulation.odometry.faults;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    lines.insert(lines.begin() + 5 + static_cast<std::ptrdiff_t>(i),
                 "planted odometry fault (true distance travelled): " + faults[i].Describe());
  }
  return lines;
}

SimulationFiles WriteSimulation(const std::string& dir, const Simulation& simulation,
                                const SimulationOptions& options) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw InputError(dir, 0, "cannot create the output folder: " + error.message());
  const std::filesystem::path base = std::filesystem::path(dir) / simulation.world.name;
  SimulationFiles files{base.string() + ".clf", base.string() + ".relations", base.string() + ".truth.txt"};

  io::CarmenWriteOptions write_options;
  write_options.comments = DescribeSimulation(simulation, options);
  // Every value reads back exactly: laser poses with an offset have 12 decimals, float32
  // readings need their shortest round-trip text, other readings the resolution's decimals.
  if (HasOffset(options)) write_options.pose_decimals = 12;
  write_options.range_decimals = RangeDecimals(options.laser.range_resolution_m);
  write_options.exact_ranges = options.laser.float32_values || write_options.range_decimals == 9;
  io::WriteCarmenLog(files.log, simulation.log, write_options);
  io::WriteRelations(files.relations, simulation.relations);
  io::WriteTrajectory(files.truth, simulation.truth);
  return files;
}

}  // namespace slamtune::sim
