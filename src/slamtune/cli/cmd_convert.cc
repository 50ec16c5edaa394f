// `slamtune convert RECORDING --out FILE.clf`: what slamtune read from a log or bag, written as a
// CARMEN log (ROBOTLASER1 lines with the laser and the robot pose, ODOM lines, the laser
// offset and max range as PARAMs), so that other tools — a Karto build, Cartographer's or
// GMapping's CARMEN readers — read exactly the scans slamtune reads: the same topic, poses at
// the scan stamps, resampled beams, reversed readings of an upside-down laser.
//
// CARMEN holds finite numbers only: a no-return written as +inf or NaN in the recording is
// written as the scan's max range (the CARMEN convention), and counted.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/io/log_summary.h"

namespace slamtune::cli {
namespace {

struct ConvertArgs {
  std::string log;
  std::string out;
  tune::LogInputOptions input;
  bool quiet = false;
};

int Convert(const ConvertArgs& args) {
  if (std::filesystem::is_directory(args.out)) throw InputError(args.out, 0, "--out is a folder; give a file name");
  io::LaserLog log = tune::ReadLog(args.log, args.input);
  const std::vector<std::string> input = io::DescribeLogInput(log);
  tune::PrintLogInput(log, args.quiet);
  const std::size_t replaced = io::PrepareForCarmen(&log);
  io::CarmenWriteOptions options;
  options.comments.push_back("converted by slamtune from " + args.log);
  for (const std::string& line : input) options.comments.push_back(line);
  options.comments.push_back(
      "ROBOTLASER1 laser pose = robot pose (+) laser offset (PARAM robot_frontlaser_*); "
      "no-returns written as the max range");
  options.pose_decimals = 9;
  options.exact_ranges = true;
  const io::CarmenWriteSummary written = io::WriteCarmenLog(args.out, log, options);  // whole or not at all
  std::printf("convert: %zu scans, %zu ODOM records%s; wrote %s\n", written.scans, written.odometry,
              replaced > 0 ? fmt::format(", {} non-finite readings written as the max range", replaced).c_str() : "",
              args.out.c_str());
  return 0;
}

const SubcommandRegistrar kConvert(Subcommand{
    "convert", "Write what slamtune reads from a log or bag as a CARMEN log (ROBOTLASER1 with laser and robot poses)",
    15, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<ConvertArgs>();
      app.add_option("RECORDING", args->log, "ROS 2 / ROS 1 bag (or a CARMEN log)")->required();
      app.add_option("--out", args->out, "CARMEN log to write (.clf)")->required();
      app.add_flag("--quiet", args->quiet, "Do not print what was read");
      AddLogInputFlags(app, args->input);
      app.footer(
          "Examples:\n"
          "  slamtune convert drive.mcap --out drive.clf\n"
          "  slamtune convert drive_bag/ --scan-topic /scan_front --base-frame base_link --out drive.clf");
      return [args]() -> int { return Convert(*args); };
    }});

}  // namespace
}  // namespace slamtune::cli
