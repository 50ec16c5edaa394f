#include "slamtune/io/carmen/carmen_records.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "slamtune/common/karto_math.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io::carmen {
namespace {

// "FLASER x (field 183)": fields are numbered from 1 with the record name as field 1, as awk does.
std::string Where(const Fields& f, std::size_t i, std::string_view what) {
  return std::string(f[0]) + " " + std::string(what) + " (field " + std::to_string(i + 1) + ")";
}

// Any number, NaN and infinities included (readings, velocities, remissions).
double Number(const Fields& f, std::size_t i, std::string_view what) {
  const auto value = ParseDouble(f[i]);
  if (!value) throw CarmenRecordError(Where(f, i, what) + " is not a number: '" + std::string(f[i]) + "'");
  return *value;
}

// A number that must be finite (poses, times, geometry).
double Finite(const Fields& f, std::size_t i, std::string_view what) {
  const double value = Number(f, i, what);
  if (!std::isfinite(value)) throw CarmenRecordError(Where(f, i, what) + " is not finite: " + std::string(f[i]));
  return value;
}

std::size_t Count(const Fields& f, std::size_t i, std::string_view what) {
  const auto value = ParseCount(f[i]);
  if (!value) throw CarmenRecordError(Where(f, i, what) + " is not a count: '" + std::string(f[i]) + "'");
  return *value;
}

// Parses n readings starting at field `first` into scan->ranges.
void ParseRanges(const Fields& f, std::size_t first, std::size_t n, LaserScanRecord* scan) {
  scan->ranges.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto value = ParseDouble(f[first + k]);
    if (!value) {
      throw CarmenRecordError(Where(f, first + k, "reading " + std::to_string(k + 1)) + " is not a number: '" +
                              std::string(f[first + k]) + "'");
    }
    scan->ranges[k] = *value;
  }
}

// Trailing `ipc_timestamp ipc_hostname logger_timestamp` starting at field i.
void ParseTimes(const Fields& f, std::size_t i, double* ipc_time, double* logger_time) {
  *ipc_time = Finite(f, i, "ipc_timestamp");
  *logger_time = Finite(f, i + 2, "logger_timestamp");
}

// No logger writes a heading of a million radians (159,000 turns, unwrapped); such a field is
// corrupt, and would send every angle computed from it into whole-turn loops.
constexpr double kMaxAbsHeadingRad = 1e6;

Pose2 ParsePose(const Fields& f, std::size_t i, std::string_view prefix) {
  const std::string p(prefix);
  const double theta = Finite(f, i + 2, p + "theta");
  if (std::fabs(theta) > kMaxAbsHeadingRad) {
    throw CarmenRecordError(Where(f, i + 2, p + "theta") + " is not a heading in radians: " + std::string(f[i + 2]) +
                            " (|theta| must be <= 1e6)");
  }
  return Pose2{Finite(f, i, p + "x"), Finite(f, i + 1, p + "y"), theta};
}

// Refuses what no laser can mean (beam_geometry.h): start_angle or fov beyond a full turn, beams
// spanning more, or a fov that contradicts n readings at angular_res (CARMEN loggers write
// fov = (n - 1) * angular_res, some n * angular_res).
void CheckGeometry(const Fields& f, double fov, std::size_t n, const LaserScanRecord& scan) {
  constexpr const char* kHint = "angles must be radians (written in degrees?)";
  if (std::fabs(scan.angle_min) > kMaxBeamAngle) {
    throw CarmenRecordError(Where(f, 2, "start_angle") + " " + std::string(f[2]) + " is beyond +-2pi: " + kHint);
  }
  if (std::fabs(fov) > kMaxBeamAngle) {
    throw CarmenRecordError(
        fmt::format("{} {} ({:.0f} deg) is more than a full turn: {}", Where(f, 3, "fov"), f[3], RadToDeg(fov), kHint));
  }
  if (const std::string problem = BeamAnglesProblem(scan.angle_min, scan.angle_increment, n); !problem.empty()) {
    throw CarmenRecordError(Where(f, 4, "angular_res") + ": " + problem);
  }
  if (n < 2) return;
  const double steps = scan.angle_increment * static_cast<double>(n - 1);
  const double tolerance = kFovTolerance + 0.01 * steps;
  if (fov < steps - tolerance || fov > steps + scan.angle_increment + tolerance) {
    throw CarmenRecordError(
        fmt::format("{} {} rad contradicts {} readings at angular_res {} rad (they span {:.6f} rad)",
                    Where(f, 3, "fov"), f[3], n, f[4], steps));
  }
}

// Shared head of ROBOTLASER1 and RAWLASER1..4 up to the remissions. `tail` is the number of
// fields after the remissions. Returns the index of the first field after the remissions.
std::size_t ParseLaserHead(const Fields& f, std::size_t tail, LaserScanRecord* scan) {
  const std::string name(f[0]);
  if (f.size() < 10) {
    throw CarmenRecordError(name + " has only " + std::to_string(f.size()) +
                            " fields; its header needs laser_type start_angle fov angular_res max_range accuracy "
                            "remission_mode num_readings");
  }
  Number(f, 1, "laser_type");
  scan->angle_min = Finite(f, 2, "start_angle");
  const double fov = Finite(f, 3, "fov");
  scan->angle_increment = Finite(f, 4, "angular_res");
  scan->max_range = Finite(f, 5, "max_range");
  if (scan->max_range <= 0)
    throw CarmenRecordError(Where(f, 5, "max_range") + " must be positive: " + std::string(f[5]));
  Number(f, 6, "accuracy");
  Number(f, 7, "remission_mode");
  const std::size_t n = Count(f, 8, "num_readings");
  if (n == 0) throw CarmenRecordError(name + " declares 0 readings");
  if (n > 1 && scan->angle_increment <= 0) {
    throw CarmenRecordError(Where(f, 4, "angular_res") + " must be positive for " + std::to_string(n) +
                            " readings: " + std::string(f[4]));
  }
  CheckGeometry(f, fov, n, *scan);
  if (f.size() < 10 + n) {
    throw CarmenRecordError(name + " declares " + std::to_string(n) + " readings but the line ends after " +
                            std::to_string(f.size() - 9) + " more fields");
  }
  const auto m = ParseCount(f[9 + n]);
  if (!m) {
    throw CarmenRecordError(name + " declares " + std::to_string(n) + " readings but field " + std::to_string(10 + n) +
                            " after them is not a remission count: '" + std::string(f[9 + n]) + "'");
  }
  const std::size_t expected = 10 + n + *m + tail;
  if (f.size() != expected) {
    throw CarmenRecordError(name + " declares " + std::to_string(n) + " readings and " + std::to_string(*m) +
                            " remissions, so expects " + std::to_string(expected) + " fields, but has " +
                            std::to_string(f.size()));
  }
  ParseRanges(f, 9, n, scan);
  for (std::size_t k = 0; k < *m; ++k) Number(f, 10 + n + k, "remission " + std::to_string(k + 1));
  return 10 + n + *m;
}

}  // namespace

LaserScanRecord ParseFlaser(const Fields& f) {
  constexpr std::size_t kTail = 9;  // x y theta odom_x odom_y odom_theta ipc host logger
  if (f.size() < 2) throw CarmenRecordError("FLASER has no reading count");
  const std::size_t n = Count(f, 1, "num_readings");
  if (n == 0) throw CarmenRecordError("FLASER declares 0 readings");
  const std::size_t after = f.size() - 2;
  if (after < kTail) {
    throw CarmenRecordError("FLASER declares " + std::to_string(n) + " readings but the line has only " +
                            std::to_string(after) + " fields after the count (" + std::to_string(n + kTail) +
                            " needed)");
  }
  if (after != n + kTail) {
    throw CarmenRecordError("FLASER declares " + std::to_string(n) + " readings but has " +
                            std::to_string(after - kTail) + " numbers before the pose");
  }
  LaserScanRecord scan;
  scan.kind = RecordKind::kFlaser;
  FlaserBeamGeometry(n, &scan.angle_min, &scan.angle_increment);
  ParseRanges(f, 2, n, &scan);
  const std::size_t p = 2 + n;
  scan.laser_pose = ParsePose(f, p, "");
  scan.robot_pose = ParsePose(f, p + 3, "odom_");
  scan.laser_offset = Between(scan.robot_pose, scan.laser_pose);
  ParseTimes(f, p + 6, &scan.ipc_time, &scan.logger_time);
  return scan;
}

LaserScanRecord ParseRobotLaser(const Fields& f) {
  constexpr std::size_t kTail = 14;  // laser pose, robot pose, tv rv fsd ssd turn_axis, ipc host logger
  LaserScanRecord scan;
  scan.kind = RecordKind::kRobotLaser1;
  const std::size_t p = ParseLaserHead(f, kTail, &scan);
  scan.laser_pose = ParsePose(f, p, "laser_");
  scan.robot_pose = ParsePose(f, p + 3, "robot_");
  for (std::size_t k = 6; k < 11; ++k) Number(f, p + k, "velocity/safety field");
  scan.laser_offset = Between(scan.robot_pose, scan.laser_pose);
  ParseTimes(f, p + 11, &scan.ipc_time, &scan.logger_time);
  return scan;
}

LaserScanRecord ParseRawLaser(const Fields& f) {
  constexpr std::size_t kTail = 3;  // ipc host logger
  LaserScanRecord scan;
  scan.kind = RecordKind::kRawLaser;
  const std::size_t p = ParseLaserHead(f, kTail, &scan);
  ParseTimes(f, p, &scan.ipc_time, &scan.logger_time);
  return scan;
}

OdomRecord ParseOdom(const Fields& f) {
  if (f.size() != 10) {
    throw CarmenRecordError("ODOM has " + std::to_string(f.size()) +
                            " fields, expects 10 (ODOM x y theta tv rv accel ipc_timestamp ipc_hostname "
                            "logger_timestamp)");
  }
  OdomRecord odom;
  odom.pose = ParsePose(f, 1, "");
  odom.tv = Number(f, 4, "tv");
  odom.rv = Number(f, 5, "rv");
  odom.accel = Number(f, 6, "accel");
  ParseTimes(f, 7, &odom.ipc_time, &odom.logger_time);
  return odom;
}

std::pair<std::string, std::string> ParseParam(const Fields& f) {
  if (f.size() < 5) {
    throw CarmenRecordError("PARAM has " + std::to_string(f.size()) +
                            " fields, expects at least 5 (PARAM name value ipc_hostname timestamp)");
  }
  Number(f, f.size() - 1, "timestamp");
  // Newer CARMEN: PARAM name value ipc_timestamp ipc_hostname logger_timestamp, both times
  // written with a decimal point (%f); older: PARAM name value ipc_hostname timestamp.
  const std::size_t n = f.size();
  const auto is_time = [&](std::size_t k) { return f[k].find('.') != std::string_view::npos && ParseDouble(f[k]); };
  const bool newer = n >= 6 && is_time(n - 3) && is_time(n - 1);
  const std::size_t value_end = newer ? n - 3 : n - 2;
  std::string value(f[2]);
  for (std::size_t k = 3; k < value_end; ++k) value.append(" ").append(f[k]);
  return {std::string(f[1]), value};
}

}  // namespace slamtune::io::carmen

namespace slamtune::io {

void FlaserBeamGeometry(std::size_t num_readings, double* angle_min, double* angle_increment) {
  *angle_min = -kPi / 2.0;
  if (num_readings <= 1) {
    *angle_increment = 0.0;
  } else if (num_readings % 2 == 0) {
    *angle_increment = kPi / static_cast<double>(num_readings);
  } else {
    *angle_increment = kPi / static_cast<double>(num_readings - 1);
  }
}

}  // namespace slamtune::io
