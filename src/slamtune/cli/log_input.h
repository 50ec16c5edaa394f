// The options every command that reads a log shares (--lenient, --no-return, --beams, and the
// choices made for a ROS recording: --scan-topic, --odom-topic, --odom-frame, --base-frame,
// --laser-offset, --max-odom-gap), turned into io::LogReadOptions; and the lines that say what
// was read and chosen, printed by each command so that no choice is silent.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"

namespace slamtune::cli {

struct LogInputOptions {
  bool lenient = false;
  double no_return = 0.0;      // m; 0 = from the log
  std::size_t max_scans = 0;   // 0 = all
  std::string beams = "node";  // io::BeamPolicy by name
  std::string scan_topic, odom_topic, odom_frame, base_frame;
  std::vector<double> laser_offset;  // X,Y,YAW when given
  double max_odom_gap_s = 0.5;

  // Whether a command offers --max-scans (one that checks a whole log does not).
  enum class MaxScans { kOffer, kOmit };
  // Adds the options to `app`.
  void AddTo(CLI::App& app, MaxScans max_scans_option = MaxScans::kOffer);
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

}  // namespace slamtune::cli
