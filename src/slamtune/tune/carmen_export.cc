#include "slamtune/tune/carmen_export.h"

#include <fmt/format.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/io/log_summary.h"

namespace slamtune::tune {
namespace {

// Refuses a fault's --out that cannot be a file before the log is read.
void RequireWritableFaultOut(const std::string& out) {
  const std::filesystem::path path(out);
  if (std::filesystem::is_directory(path)) throw InputError(out, 0, "--out is a folder; give a file name");
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  if (!std::filesystem::is_directory(folder)) {
    throw InputError(out, 0, "--out: cannot write: the folder " + folder.string() + " does not exist");
  }
}

}  // namespace

std::string DescribeExport(const CarmenExport& exported, const std::string& out) {
  return fmt::format("{} scans, {} ODOM records{}; wrote {}", exported.written.scans, exported.written.odometry,
                     exported.non_finite_readings > 0 ? fmt::format(", {} non-finite readings written as the max range",
                                                                    exported.non_finite_readings)
                                                      : "",
                     out);
}

CarmenExport ConvertToCarmen(const ConvertOptions& options) {
  if (std::filesystem::is_directory(options.out)) {
    throw InputError(options.out, 0, "--out is a folder; give a file name");
  }
  io::LaserLog log = ReadLog(options.log, options.input);
  const std::vector<std::string> input = io::DescribeLogInput(log);
  PrintLogInput(log, options.quiet);
  CarmenExport out;
  out.non_finite_readings = io::PrepareForCarmen(&log);
  io::CarmenWriteOptions write;
  write.comments.push_back("converted by slamtune from " + options.log);
  for (const std::string& line : input) write.comments.push_back(line);
  write.comments.push_back(
      "ROBOTLASER1 laser pose = robot pose (+) laser offset (PARAM robot_frontlaser_*); "
      "no-returns written as the max range");
  write.pose_decimals = 9;
  write.exact_ranges = true;
  out.written = io::WriteCarmenLog(options.out, log, write);  // whole or not at all
  return out;
}

FaultOutcome PlantFaultsAndWrite(const FaultOptions& options) {
  if (options.faults.empty()) {
    throw InputError("--fault: required, at least one KIND,START_M,LENGTH_M[,MAGNITUDE] (see slamtune fault --help)");
  }
  std::vector<sim::OdometryFault> faults;
  for (const std::string& text : options.faults) faults.push_back(sim::ParseOdometryFault(text));
  RequireWritableFaultOut(options.out);
  io::LaserLog log = ReadLog(options.log, options.input);
  const std::vector<std::string> input = io::DescribeLogInput(log);
  PrintLogInput(log, options.quiet);
  FaultOutcome out;
  out.planted = sim::PlantLogFaults(log, faults);
  out.exported.non_finite_readings = io::PrepareForCarmen(&log, /*keep_flaser=*/true);

  io::CarmenWriteOptions write;
  write.comments.push_back("odometry faults planted by slamtune into " + options.log +
                           fmt::format(", located by its odometric travel ({:.3f} m over {} robot poses in {})",
                                       out.planted.travel_m, out.planted.poses, out.planted.order));
  for (const sim::PlantedLogFault& fault : out.planted.faults) write.comments.push_back("planted: " + fault.Describe());
  for (const std::string& line : input) write.comments.push_back(line);
  write.comments.push_back(
      "readings and timestamps as recorded; laser and robot poses of every scan and every ODOM "
      "pose carry the faults; no-returns written as the max range");
  write.pose_decimals = 9;
  write.time_decimals = log.recording ? 9 : 6;  // a ROS stamp's nanoseconds, a CARMEN log's microseconds
  write.exact_ranges = true;
  out.exported.written = io::WriteCarmenLog(options.out, log, write);  // whole or not at all
  return out;
}

}  // namespace slamtune::tune
