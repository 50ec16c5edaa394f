// How every command reads a log: the options the commands share (--lenient, --no-return,
// --max-scans, --beams, and the choices made for a ROS recording: --scan-topic, --odom-topic,
// --odom-frame, --base-frame, --laser-offset, --max-odom-gap; their flags: cli/input_flags.h),
// turned into io::LogReadOptions and kept in the run database; and the lines that say what was
// read and chosen, printed by each command so that no choice is silent.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"

namespace slamtune::tune {

struct LogInputOptions {
  bool lenient = false;                                        // skip malformed records (counted) instead of failing
  double no_return = 0.0;                                      // m; readings >= it are no-returns; 0 = the log's own
  std::size_t max_scans = 0;                                   // read only the first N scans; 0 = all
  std::string beams = "node";                                  // io::BeamPolicy by name: scans whose beam count changes
  std::string scan_topic, odom_topic, odom_frame, base_frame;  // ROS recordings; "" = chosen from the recording
  std::vector<double> laser_offset;                            // X, Y, YAW (m, m, rad) when given; else the tf tree's
  double max_odom_gap_s = 0.5;                                 // s; odometry samples farther apart are not interpolated

  // Throws InputError naming the option for a bad value.
  io::LogReadOptions ToReadOptions() const;
  // Everything that changes what is read, for the run database and --resume.
  nlohmann::json ToJson() const;
  static LogInputOptions FromJson(const nlohmann::json& j);
  // InputError when a slice of the log was asked for (--max-scans) but no LOG is read: the
  // built-in `world` is simulated whole, so the slice would be ignored without a word.
  void RequireLogForSlice(const std::string& world) const;
};

// The log at `path` read with `options` (io::ReadLaserLog).
io::LaserLog ReadLog(const std::string& path, const LogInputOptions& options);

// What was read and chosen (io::DescribeLogInput) on stderr; with `quiet` only the lines that
// say data of the recording is not used (io::InputLossLines): quiet silences progress, not
// data loss.
void PrintLogInput(const io::LaserLog& log, bool quiet);

}  // namespace slamtune::tune
