#include "slamtune/io/carmen/carmen_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <sstream>

#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_records.h"

namespace slamtune::io {
namespace {

// The CARMEN header every log of the Freiburg datasets starts with (formats used here only).
constexpr const char* kFormatComments[] = {
    "message_name [message contents] ipc_timestamp ipc_hostname logger_timestamp",
    "message formats defined: PARAM ODOM FLASER ROBOTLASER1",
    "PARAM param_name param_value",
    "ODOM x y theta tv rv accel",
    "FLASER num_readings [range_readings] x y theta odom_x odom_y odom_theta",
    "ROBOTLASER1 laser_type start_angle field_of_view angular_resolution maximum_range accuracy remission_mode "
    "num_readings [range_readings] num_remissions [remissions] laser_pose_x laser_pose_y laser_pose_theta "
    "robot_pose_x robot_pose_y robot_pose_theta laser_tv laser_rv forward_safety_dist side_safty_dist turn_axis",
};

// Beam angles are compared with the FLASER rule up to rounding of the caller's arithmetic.
constexpr double kAngleTolerance = 1e-9;

bool HasSpace(const std::string& text) {
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) return true;
  }
  return false;
}

void RequireDecimals(const char* field, int value, int max) {
  if (value < 0 || value > max)
    throw InputError(fmt::format("carmen writer {} = {}: must be in [0, {}]", field, value, max));
}

void RequireFinitePose(const Pose2& p, const char* what, std::size_t index) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta)) {
    throw InputError(fmt::format("cannot write {} {}: pose {} is not finite", what, index, ToString(p)));
  }
}

// Checks every value first, so nothing is written for a log that cannot be.
void CheckWritable(const LaserLog& log) {
  for (const auto& [name, value] : log.params) {
    if (name.empty() || value.empty() || HasSpace(name) || HasSpace(value)) {
      throw InputError(
          fmt::format("cannot write PARAM '{}' = '{}': name and value must be non-empty words", name, value));
    }
  }
  for (std::size_t i = 0; i < log.odometry.size(); ++i) {
    const OdomRecord& r = log.odometry[i];
    RequireFinitePose(r.pose, "ODOM record", i);
    if (!std::isfinite(r.tv) || !std::isfinite(r.rv) || !std::isfinite(r.accel) || !std::isfinite(r.ipc_time) ||
        !std::isfinite(r.logger_time)) {
      throw InputError(fmt::format("cannot write ODOM record {}: a velocity or timestamp is not finite", i));
    }
  }
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScanRecord& s = log.scans[i];
    RequireFinitePose(s.laser_pose, "laser scan", i);
    RequireFinitePose(s.robot_pose, "laser scan", i);
    if (!std::isfinite(s.ipc_time) || !std::isfinite(s.logger_time)) {
      throw InputError(fmt::format("cannot write laser scan {}: a timestamp is not finite", i));
    }
    if (s.kind == RecordKind::kFlaser) {
      double angle_min = 0.0, increment = 0.0;
      FlaserBeamGeometry(s.ranges.size(), &angle_min, &increment);
      if (std::fabs(s.angle_min - angle_min) > kAngleTolerance ||
          std::fabs(s.angle_increment - increment) > kAngleTolerance) {
        throw InputError(fmt::format(
            "cannot write laser scan {} as FLASER: its beams (first {} rad, step {} rad) are not the FLASER "
            "convention for {} readings (first {} rad, step {} rad); give it another kind to write ROBOTLASER1",
            i, s.angle_min, s.angle_increment, s.ranges.size(), angle_min, increment));
      }
    } else if (!std::isfinite(s.max_range) || !std::isfinite(s.angle_min) || !std::isfinite(s.angle_increment)) {
      throw InputError(
          fmt::format("cannot write laser scan {} as ROBOTLASER1: max range {}, first angle {}, step {} "
                      "must be finite",
                      i, s.max_range, s.angle_min, s.angle_increment));
    }
    for (std::size_t b = 0; b < s.ranges.size(); ++b) {
      if (!std::isfinite(s.ranges[b])) {
        throw InputError(fmt::format("cannot write laser scan {}: reading {} is {} (FLASER holds finite numbers only)",
                                     i, b, s.ranges[b]));
      }
    }
  }
}

void AppendPose(fmt::memory_buffer& out, const Pose2& p, int decimals) {
  fmt::format_to(std::back_inserter(out), " {:.{}f} {:.{}f} {:.{}f}", p.x, decimals, p.y, decimals, p.theta, decimals);
}

CarmenWriteSummary WriteChecked(std::ostream& out, const LaserLog& log, const CarmenWriteOptions& options);

}  // namespace

void CarmenWriteOptions::Validate() const {
  if (hostname.empty() || HasSpace(hostname)) {
    throw InputError(fmt::format("carmen writer hostname = '{}': must be one non-empty word", hostname));
  }
  for (const std::string& comment : comments) {
    if (comment.find('\n') != std::string::npos) {
      throw InputError(fmt::format("carmen writer comment '{}': must be a single line", comment));
    }
  }
  RequireDecimals("range_decimals", range_decimals, 9);
  RequireDecimals("pose_decimals", pose_decimals, 12);
  RequireDecimals("time_decimals", time_decimals, 9);
}

std::size_t PrepareForCarmen(LaserLog* log, bool keep_flaser) {
  std::size_t replaced = 0;
  for (LaserScanRecord& scan : log->scans) {
    if (!(keep_flaser && scan.kind == RecordKind::kFlaser)) scan.kind = RecordKind::kRobotLaser1;
    if (!std::isfinite(scan.max_range)) {
      double largest = 0.0;
      for (double r : scan.ranges) largest = std::isfinite(r) ? std::max(largest, r) : largest;
      scan.max_range = std::max(largest + 1.0, 1.0);
    }
    for (double& r : scan.ranges) {
      if (!std::isfinite(r)) {
        r = scan.max_range;
        ++replaced;
      }
    }
  }
  const Pose2 offset = log->scans.empty() ? Pose2{} : log->scans.front().laser_offset;
  log->params["robot_frontlaser_offset"] = fmt::format("{}", offset.x);
  log->params["robot_frontlaser_side_offset"] = fmt::format("{}", offset.y);
  log->params["robot_frontlaser_angular_offset"] = fmt::format("{}", offset.theta);
  if (!log->scans.empty()) log->params["laser_front_laser_max_range"] = fmt::format("{}", log->scans.front().max_range);
  return replaced;
}

CarmenWriteSummary WriteCarmenLog(std::ostream& out, const LaserLog& log, const CarmenWriteOptions& options) {
  options.Validate();
  CheckWritable(log);
  return WriteChecked(out, log, options);
}

CarmenWriteSummary WriteCarmenLog(const std::string& path, const LaserLog& log, const CarmenWriteOptions& options) {
  options.Validate();
  CheckWritable(log);
  // Whole or not at all (common/atomic_file.h): a reader never sees half a log.
  std::ostringstream text;
  CarmenWriteSummary summary = WriteChecked(text, log, options);
  WriteFileAtomically(path, text.view());
  return summary;
}

namespace {

CarmenWriteSummary WriteChecked(std::ostream& out, const LaserLog& log, const CarmenWriteOptions& options) {
  CarmenWriteSummary summary;
  fmt::memory_buffer buffer;
  const auto flush = [&] {
    out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    buffer.clear();
  };
  const auto line_end = [&] {
    buffer.push_back('\n');
    ++summary.lines;
    if (buffer.size() > (1 << 16)) flush();
  };
  const auto trailer = [&](double ipc_time, double logger_time) {
    fmt::format_to(std::back_inserter(buffer), " {:.{}f} {} {:.{}f}", ipc_time, options.time_decimals, options.hostname,
                   logger_time, options.time_decimals);
    line_end();
  };

  for (const char* comment : kFormatComments) {
    fmt::format_to(std::back_inserter(buffer), "# {}", comment);
    line_end();
    ++summary.comments;
  }
  for (const std::string& comment : options.comments) {
    fmt::format_to(std::back_inserter(buffer), "# {}", comment);
    line_end();
    ++summary.comments;
  }
  for (const auto& [name, value] : log.params) {
    fmt::format_to(std::back_inserter(buffer), "PARAM {} {} {} 0", name, value, options.hostname);
    line_end();
    ++summary.params;
  }
  // Merge by ipc_time, ODOM first when equal; each list keeps its own order.
  std::size_t o = 0, s = 0;
  while (o < log.odometry.size() || s < log.scans.size()) {
    const bool odometry_next =
        o < log.odometry.size() && (s >= log.scans.size() || log.odometry[o].ipc_time <= log.scans[s].ipc_time);
    if (odometry_next) {
      const OdomRecord& r = log.odometry[o++];
      buffer.append(std::string_view("ODOM"));
      AppendPose(buffer, r.pose, options.pose_decimals);
      fmt::format_to(std::back_inserter(buffer), " {:.{}f} {:.{}f} {:.{}f}", r.tv, options.pose_decimals, r.rv,
                     options.pose_decimals, r.accel, options.pose_decimals);
      trailer(r.ipc_time, r.logger_time);
      ++summary.odometry;
    } else {
      const LaserScanRecord& r = log.scans[s++];
      const bool flaser = r.kind == RecordKind::kFlaser;
      if (flaser) {
        fmt::format_to(std::back_inserter(buffer), "FLASER {}", r.ranges.size());
      } else {
        // Angles and max range in shortest round-trip form: the geometry reads back exactly.
        const double fov = r.angle_increment * static_cast<double>(r.ranges.size() > 0 ? r.ranges.size() - 1 : 0);
        fmt::format_to(std::back_inserter(buffer), "ROBOTLASER1 0 {} {} {} {} 0 0 {}", r.angle_min, fov,
                       r.angle_increment, r.max_range, r.ranges.size());
      }
      if (options.exact_ranges) {
        for (double range : r.ranges) fmt::format_to(std::back_inserter(buffer), " {}", range);
      } else {
        for (double range : r.ranges)
          fmt::format_to(std::back_inserter(buffer), " {:.{}f}", range, options.range_decimals);
      }
      if (!flaser) buffer.append(std::string_view(" 0"));  // no remissions
      AppendPose(buffer, r.laser_pose, options.pose_decimals);
      AppendPose(buffer, r.robot_pose, options.pose_decimals);
      if (!flaser) buffer.append(std::string_view(" 0 0 0 0 0"));  // tv rv forward/side safety turn_axis
      trailer(r.ipc_time, r.logger_time);
      ++summary.scans;
      if (!flaser) ++summary.robotlaser1;
    }
  }
  flush();
  return summary;
}

}  // namespace

}  // namespace slamtune::io
