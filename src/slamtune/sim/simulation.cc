#include "slamtune/sim/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/io/carmen/carmen_records.h"
#include "slamtune/sim/random.h"
#include "slamtune/sim/ray_caster.h"
#include "slamtune/sim/route.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
namespace {

constexpr uint64_t kLaserStream = 1;
constexpr uint64_t kOdometryStream = 2;

void RequireRange(const char* field, double value, double low, double high, bool low_open) {
  const bool ok = std::isfinite(value) && (low_open ? value > low : value >= low) && value <= high;
  if (!ok)
    throw InputError(fmt::format("{} = {}: must be in {}{}, {}]", field, value, low_open ? "(" : "[", low, high));
}

// Rounds to 6 decimals: k / 1e6 is the double nearest to the decimal that "%.6f" prints, so
// timestamps name exactly the same instants in every file, and the in-memory log equals the
// written log read back (times, poses and velocities are written with 6 decimals).
double Round6(double v) { return std::round(v * 1e6) / 1e6; }

Pose2 Round6(const Pose2& p) { return {Round6(p.x), Round6(p.y), Round6(p.theta)}; }

// The same at 12 decimals (k / 1e12 is exact for |v| < 9000 m), for laser poses with an offset.
double Round12(double v) { return std::round(v * 1e12) / 1e12; }
Pose2 Round12(const Pose2& p) { return {Round12(p.x), Round12(p.y), Round12(p.theta)}; }

bool IsZero(const Pose2& p) { return p.x == 0.0 && p.y == 0.0 && p.theta == 0.0; }

}  // namespace

void SimulationOptions::Validate() const {
  bool known = false;
  std::string names;
  for (const WorldInfo& info : ListWorlds()) {
    known = known || info.name == world;
    names += (names.empty() ? "" : ", ") + info.name;
  }
  if (!known) throw InputError(fmt::format("world = '{}': must be one of {}", world, names));
  laser.Validate();
  odometry.Validate();
  relations.Validate();
  RequireRange("speed_mps", speed_mps, 0.0, 5.0, true);
  RequireRange("scan_rate_hz", scan_rate_hz, 0.0, 100.0, true);
  RequireRange("step_length_m", step_length_m, 0.0, 1.0, true);
  RequireRange("start_time_s", start_time_s, 0.0, 1e9, false);
  RequireRange("laser_offset.x", laser_offset.x, -5.0, 5.0, false);
  RequireRange("laser_offset.y", laser_offset.y, -5.0, 5.0, false);
  RequireRange("laser_offset.theta", laser_offset.theta, -kPi, kPi, false);
  if (max_scans < 1) throw InputError("max_scans = 0: must be >= 1");
}

std::string SimulationSummary::Report() const {
  std::string faults;
  for (const std::string& fault : odometry_faults) faults += "\nplanted odometry fault: " + fault;
  return fmt::format(
      "world {} (seed {}): {} scans, {} ODOM records, path {:.1f} m in {:.1f} s\n"
      "readings: {} ({} no-return, {:.1f}%)\n"
      "odometry error vs truth: final {:.2f} m / {:.1f} deg, max {:.2f} m / {:.1f} deg\n"
      "relations: {} local, {} revisits (longest gap {:.0f} s){}",
      world, seed, scans, odometry_records, path_length_m, duration_s, readings, no_return_readings,
      readings ? 100.0 * no_return_readings / readings : 0.0, final_position_error_m, RadToDeg(final_heading_error_rad),
      max_position_error_m, RadToDeg(max_heading_error_rad), local_relations, revisit_relations, longest_revisit_gap_s,
      faults);
}

namespace {

// The beam geometry the records state: FLASER when the beams follow its convention
// (carmen_reader.h), with the reader's exact values so the log reads back identical;
// ROBOTLASER1, which states its geometry, otherwise.
struct RecordGeometry {
  io::RecordKind kind = io::RecordKind::kRobotLaser1;
  double angle_min = 0.0;
  double angle_increment = 0.0;
};

RecordGeometry RecordGeometryOf(const LaserOptions& laser) {
  RecordGeometry g{io::RecordKind::kRobotLaser1, laser.angle_min(), laser.angle_increment()};
  double flaser_min = 0.0, flaser_increment = 0.0;
  io::FlaserBeamGeometry(laser.beams, &flaser_min, &flaser_increment);
  if (std::fabs(flaser_min - g.angle_min) < 1e-12 && std::fabs(flaser_increment - g.angle_increment) < 1e-12) {
    g = {io::RecordKind::kFlaser, flaser_min, flaser_increment};
  }
  return g;
}

// The PARAM records and the no-return rule of the log, as a CARMEN logger writes them.
void WriteLogHeader(const LaserOptions& laser, const Pose2& offset, io::LaserLog& log) {
  log.path = "<memory>";
  const bool has_offset = !IsZero(offset);
  log.params = {{kMaxRangeParam, fmt::format("{}", laser.max_range())},
                {"laser_front_laser_fov", fmt::format("{}", laser.fov_deg)},
                {"laser_front_laser_resolution", fmt::format("{}", laser.fov_deg / (laser.beams - 1))},
                {"robot_frontlaser_offset", has_offset ? fmt::format("{}", offset.x) : "0.0"}};
  if (has_offset) {
    log.params["robot_frontlaser_side_offset"] = fmt::format("{}", offset.y);
    log.params["robot_frontlaser_angular_offset"] = fmt::format("{}", offset.theta);
  }
  log.no_return_value = laser.max_range();
  log.no_return_rule = std::string("PARAM ") + kMaxRangeParam;
}

// Drives the robot along the route and records, in time order, its odometry every
// step_length_m and a scan at scan_rate_hz (ODOM first at equal times).
class Recorder {
 public:
  Recorder(const SimulationOptions& options, const Route& route, const World& world,
           const OdometryNoiseOptions& odometry, Simulation& sim)
      : options_(options),
        route_(route),
        caster_(world.walls),
        geometry_(RecordGeometryOf(options.laser)),
        laser_random_(StreamSeed(options.seed, kLaserStream)),
        odometry_(route.PoseAt(0.0), odometry, StreamSeed(options.seed, kOdometryStream)),
        previous_true_(route.PoseAt(0.0)),
        sim_(sim) {}

  void Record(std::size_t num_scans, std::size_t num_odometry) {
    sim_.log.scans.reserve(num_scans);
    sim_.log.odometry.reserve(num_odometry);
    sim_.truth.reserve(num_scans);
    std::size_t next_scan = 0, next_odometry = 0;
    while (next_scan < num_scans || next_odometry < num_odometry) {
      const double scan_time = Round6(options_.start_time_s + next_scan / options_.scan_rate_hz);
      const double odometry_time =
          Round6(options_.start_time_s + next_odometry * options_.step_length_m / options_.speed_mps);
      const bool is_odometry = next_odometry < num_odometry && (next_scan >= num_scans || odometry_time <= scan_time);
      const double time = is_odometry ? odometry_time : scan_time;
      const double s = std::min((time - options_.start_time_s) * options_.speed_mps, route_.length());
      const Pose2 true_pose = MoveTo(s);
      if (is_odometry) {
        RecordOdometry(time, s);
        ++next_odometry;
      } else {
        RecordScan(time, true_pose);
        ++next_scan;
      }
    }
  }

  io::RecordKind kind() const { return geometry_.kind; }

 private:
  // The true pose at route position s; the odometry model follows the motion since the last call.
  Pose2 MoveTo(double s) {
    const Pose2 true_pose = route_.PoseAt(s);
    if (s > previous_s_) odometry_.Advance(Between(previous_true_, true_pose));
    previous_s_ = s;
    previous_true_ = true_pose;
    return true_pose;
  }

  void RecordOdometry(double time, double s) {
    io::OdomRecord record;
    record.pose = Round6(odometry_.pose());
    record.tv = Round6(options_.speed_mps);
    record.rv = Round6(options_.speed_mps * route_.CurvatureAt(s));
    record.ipc_time = time;
    record.logger_time = Round6(time - options_.start_time_s);
    sim_.log.odometry.push_back(record);
  }

  void RecordScan(double time, const Pose2& true_pose) {
    const Pose2& offset = options_.laser_offset;
    const bool has_offset = !IsZero(offset);
    const Pose2 true_laser = has_offset ? Compose(true_pose, offset) : true_pose;
    SimulatedScan scan = SimulateScan(caster_, true_laser, options_.laser, laser_random_);
    io::LaserScanRecord record;
    record.kind = geometry_.kind;
    record.angle_min = geometry_.angle_min;
    record.angle_increment = geometry_.angle_increment;
    record.max_range = options_.laser.max_range();
    record.ranges = std::move(scan.ranges);
    record.no_returns = scan.no_returns;
    record.robot_pose = Round6(odometry_.pose());
    record.laser_pose = has_offset ? Round12(Compose(record.robot_pose, offset)) : record.robot_pose;
    record.laser_offset = Between(record.robot_pose, record.laser_pose);  // as the reader derives it
    record.ipc_time = time;
    record.logger_time = Round6(time - options_.start_time_s);
    sim_.log.scans.push_back(std::move(record));
    sim_.truth.push_back(io::TimedPose{time, true_laser});
  }

  const SimulationOptions& options_;
  const Route& route_;
  const RayCaster caster_;
  const RecordGeometry geometry_;
  Random laser_random_;
  OdometryModel odometry_;
  double previous_s_ = 0.0;
  Pose2 previous_true_;
  Simulation& sim_;
};

// The record counts and reading totals a reader of the written log would count.
void CountRecords(io::RecordKind kind, io::LaserLog& log) {
  log.record_counts = {{kind == io::RecordKind::kFlaser ? "FLASER" : "ROBOTLASER1", log.scans.size()},
                       {"ODOM", log.odometry.size()},
                       {"PARAM", log.params.size()}};
  for (const io::LaserScanRecord& scan : log.scans) {
    log.total_readings += scan.ranges.size();
    log.total_no_returns += scan.no_returns;
  }
}

SimulationSummary Summarize(const Simulation& sim, const SimulationOptions& options, const Route& route,
                            const RelationSample& relations) {
  SimulationSummary summary;
  const io::LaserLog& log = sim.log;
  summary.world = sim.world.name;
  summary.seed = options.seed;
  summary.scans = log.scans.size();
  summary.odometry_records = log.odometry.size();
  summary.path_length_m = route.length();
  summary.duration_s = sim.truth.back().time - sim.truth.front().time;
  for (std::size_t k = 0; k < log.scans.size(); ++k) {
    const Pose2& odom = log.scans[k].laser_pose;
    const Pose2& truth = sim.truth[k].pose;
    const double position_error = std::sqrt(SquaredDistance(odom, truth));
    const double heading_error = std::fabs(NormalizeAngle(odom.theta - truth.theta));
    summary.max_position_error_m = std::max(summary.max_position_error_m, position_error);
    summary.max_heading_error_rad = std::max(summary.max_heading_error_rad, heading_error);
    summary.final_position_error_m = position_error;
    summary.final_heading_error_rad = heading_error;
    summary.readings += log.scans[k].ranges.size();
    summary.no_return_readings += log.scans[k].no_returns;
  }
  summary.local_relations = relations.local_pairs;
  summary.revisit_relations = relations.revisit_pairs;
  summary.longest_revisit_gap_s = relations.longest_revisit_gap_s;
  for (const OdometryFault& fault : sim.odometry.faults) summary.odometry_faults.push_back(fault.Describe());
  return summary;
}

}  // namespace

Simulation Simulate(const SimulationOptions& options) {
  options.Validate();
  Simulation sim;
  sim.world = MakeWorld(options.world);
  const Route route(sim.world.waypoints, sim.world.turn_radius);
  const double duration = route.length() / options.speed_mps;
  const std::size_t num_scans = static_cast<std::size_t>(std::floor(duration * options.scan_rate_hz + 1e-9)) + 1;
  const std::size_t num_odometry =
      static_cast<std::size_t>(std::floor(route.length() / options.step_length_m + 1e-9)) + 1;
  if (num_scans > options.max_scans) {
    throw InputError(
        fmt::format("scan_rate_hz = {}, speed_mps = {}: world '{}' would give {} scans, above max_scans = {}",
                    options.scan_rate_hz, options.speed_mps, options.world, num_scans, options.max_scans));
  }
  sim.odometry = options.odometry;
  if (options.plant_world_faults) {
    for (const OdometryFault& fault : sim.world.odometry_faults) sim.odometry.faults.push_back(fault);
  }
  sim.odometry.Validate();

  WriteLogHeader(options.laser, options.laser_offset, sim.log);
  Recorder recorder(options, route, sim.world, sim.odometry, sim);
  recorder.Record(num_scans, num_odometry);
  CountRecords(recorder.kind(), sim.log);

  RelationSample relations = SampleRelations(sim.truth, options.relations);
  sim.summary = Summarize(sim, options, route, relations);
  sim.relations = std::move(relations.relations);
  return sim;
}

}  // namespace slamtune::sim
