// What is in a laser log, at a glance: the numbers `slamtune info` prints. Computed from an
// io::LaserLog as read (carmen_reader.h), so it also describes simulated logs.
//
// Conventions: times are laser ipc_timestamps; the duration runs from the first to the last
// scan in file order (intel's file order is not time order, see time_backward_steps); path
// length and rotation add up the increments between consecutive laser poses (the odometric
// laser poses of the log), |Δxy| and |normalize(Δθ)|.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/io/laser_log.h"

namespace slamtune::io {

struct LogSummary {
  std::string path;
  bool compressed = false;
  bool stopped_at_max_scans = false;  // only a slice of the log was read
  std::size_t lines = 0;
  // Records per type name as in the file ("#" = comment lines), skipped ones included.
  std::map<std::string, std::size_t> record_counts;
  std::size_t scans = 0;
  std::size_t odometry_records = 0;
  std::size_t params = 0;
  // Time span of the scans (s).
  double first_time_s = 0.0;
  double last_time_s = 0.0;
  double duration_s = 0.0;    // last - first
  double scan_rate_hz = 0.0;  // (scans - 1) / duration, 0 if undefined
  // Beam geometry of the first scan; *_varies say whether any other scan differs.
  std::size_t readings_per_scan = 0;
  std::size_t readings_per_scan_min = 0;
  std::size_t readings_per_scan_max = 0;
  bool readings_per_scan_varies = false;
  double angle_min_deg = 0.0;
  double angle_max_deg = 0.0;     // angle of the last beam
  double angular_span_deg = 0.0;  // angle_max - angle_min
  double angular_resolution_deg = 0.0;
  bool geometry_varies = false;
  // Ranges (m). The largest finite reading, and the largest reading below the no-return value.
  double min_reading_m = 0.0;
  double max_reading_m = 0.0;
  double max_valid_reading_m = 0.0;
  double no_return_value_m = 0.0;
  std::string no_return_rule;
  std::size_t readings = 0;
  std::size_t no_returns = 0;
  double no_return_fraction = 0.0;
  // Odometry of the laser poses in file order.
  double odometry_path_m = 0.0;
  double odometry_rotation_rad = 0.0;
  double odometry_rotation_deg = 0.0;
  // Anomalies.
  std::size_t time_backward_steps = 0;
  double largest_backward_step_s = 0.0;
  std::size_t unknown_records = 0;
  std::size_t skipped_records = 0;
  std::vector<std::string> skipped_reasons;
  std::vector<std::string> input;  // DescribeLogInput
};

LogSummary SummarizeLog(const LaserLog& log);

// What was read and every choice made, one line each: for a ROS recording its format, the
// scan topic, odometry source, laser offset and the scans that could not be used (each with
// the rule that chose it); for any log the beam geometries seen and what was done about them,
// and records skipped under --lenient. Commands print these before they work on the log.
std::vector<std::string> DescribeLogInput(const LaserLog& log);
// The lines of DescribeLogInput that say data of the recording is not used (scans not used,
// and why; records skipped; a recording cut off): what a command prints with --quiet too.
std::vector<std::string> InputLossLines(const LaserLog& log);
// The "beams:" lines of DescribeLogInput: the geometries seen, the scans each node drops for their
// reading count (beam_geometry.h ExpectedReadings) and what --beams did.
std::vector<std::string> BeamLines(const LaserLog& log);
// Those lines as (name, value) rows, split at their first ": ", for tables and reports.
std::vector<std::pair<std::string, std::string>> InputRows(const std::vector<std::string>& lines);

// Human-readable two-column table, one quantity per line.
std::string FormatLogSummary(const LogSummary& summary);

}  // namespace slamtune::io
