// `slamtune simulate`: a robot drives a built-in world (world_catalog.h) at constant speed,
// scanning with a simulated laser (laser_model.h) and counting wheel odometry with drift
// (odometry_model.h). The result is the same in-memory log the CARMEN reader produces for a
// real dataset, plus the true laser poses and Freiburg-style relations (relation_sampler.h),
// so the SLAM engine, metrics and optimiser run on it exactly as on recorded data.
//
// Timing: laser scan k is at start_time + k / scan_rate, ODOM record j at start_time +
// j * step_length / speed; both rounded to whole microseconds so the %.6f timestamps written to
// the log, relations and truth files denote the same doubles. Recorded poses and velocities
// are rounded to 6 decimals and readings to the range resolution (1 mm), so the in-memory
// log equals the written log read back by io::ReadCarmenLog, value for value. Odometry is
// integrated over every interval between consecutive records and describes the robot base.
//
// Laser mounting offset O (laser in the robot frame, zero by default): the laser looks from
// true base pose (+) O, a scan's robot pose is the odometry at that instant and its laser pose
// robot (+) O, rounded to 12 decimals (the log then writes poses with 12); the truth file and
// relations follow the true laser pose, as a SLAM trajectory of sensor poses does. With O = 0
// the laser pose is the robot pose. The offset is also written as the CARMEN PARAMs
// robot_frontlaser_offset, _side_offset and _angular_offset.
//
// Scans are FLASER records when the laser's beams follow the FLASER convention of the reader
// (io::FlaserBeamGeometry: 180 deg field of view and an odd beam count such as the default
// 181, or 361), and ROBOTLASER1 records, which state their geometry, for any other laser.
//
// Faults: the world's planted odometry faults (World::odometry_faults) are added after those of
// `odometry.faults` unless plant_world_faults is false; both are located by true distance travelled.
//
// Determinism: everything follows from `seed`; laser noise and odometry noise use separate
// streams (random.h), so e.g. changing the beam count leaves the odometry unchanged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/sim/laser_model.h"
#include "slamtune/sim/odometry_model.h"
#include "slamtune/sim/relation_sampler.h"
#include "slamtune/sim/world.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {

// The CARMEN PARAM that carries the laser's maximum range, i.e. the no-return value.
inline constexpr const char* kMaxRangeParam = "laser_front_laser_max_range";

struct SimulationOptions {
  uint64_t seed = 1;                  // all randomness follows from it
  std::string world = kDefaultWorld;  // a name from ListWorlds()
  LaserOptions laser;
  OdometryNoiseOptions odometry;
  RelationSamplingOptions relations;
  double speed_mps = 0.5;          // m/s, constant along the route, in (0, 5]
  double scan_rate_hz = 5.0;       // laser scans per second, in (0, 100]
  double step_length_m = 0.05;     // m: spacing of ODOM records (odometry is integrated per record), in (0, 1]
  double start_time_s = 100.0;     // s: timestamp of the first record, in [0, 1e9]
  Pose2 laser_offset;              // laser in the robot frame (m, m, rad): |x|, |y| <= 5, |theta| <= pi
  std::size_t max_scans = 200000;  // refuse settings that would produce more scans than this
  // false: leave out the world's planted faults, e.g. to measure the error a fault world would
  // have without its failure (its healthy twin); faults in `odometry.faults` still apply.
  bool plant_world_faults = true;

  // Throws InputError naming the field, its value and the rule (checks the nested options too).
  void Validate() const;
};

// What was simulated, for the CLI and the tests.
struct SimulationSummary {
  std::string world;
  uint64_t seed = 0;
  std::size_t scans = 0;
  std::size_t odometry_records = 0;
  std::size_t readings = 0;
  std::size_t no_return_readings = 0;  // readings equal to the max range
  double path_length_m = 0.0;
  double duration_s = 0.0;
  // Odometry versus truth at the laser scans (position in m, heading in rad).
  double final_position_error_m = 0.0;
  double max_position_error_m = 0.0;
  double final_heading_error_rad = 0.0;
  double max_heading_error_rad = 0.0;
  std::size_t local_relations = 0;
  std::size_t revisit_relations = 0;
  double longest_revisit_gap_s = 0.0;
  std::vector<std::string> odometry_faults;  // planted faults, described (OdometryFault::Describe)

  // A few human-readable lines.
  std::string Report() const;
};

struct Simulation {
  World world;
  // The odometry the log was recorded with: the options' noise, with the world's planted faults
  // after the options' own.
  OdometryNoiseOptions odometry;
  io::LaserLog log;                  // laser scans and ODOM records, each in time order
  std::vector<io::TimedPose> truth;  // true laser pose at each scan (robot (+) laser_offset)
  std::vector<io::Relation> relations;
  SimulationSummary summary;
};

// Validates `options` first (InputError), then simulates.
Simulation Simulate(const SimulationOptions& options);

}  // namespace slamtune::sim
