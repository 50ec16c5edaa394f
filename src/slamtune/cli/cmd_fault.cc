// `slamtune fault LOG --fault KIND,START_M,LENGTH_M[,MAGNITUDE] --out OUT.clf`: a recording with
// planted odometry failures (sim/log_faults.h), written as a CARMEN log, so that a tuner's repair
// of a broken front end can be measured on real scans against the recording's own relations.
// Faults take the form and meaning of `simulate --fault` (sim/odometry_fault.h), located by the
// log's odometric travel; the scans' readings and timestamps are kept. FLASER scans stay FLASER,
// others become ROBOTLASER1 as `convert` writes them (io::PrepareForCarmen).
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/sim/log_faults.h"

namespace slamtune::cli {
namespace {

struct FaultArgs {
  std::string log;
  std::string out;
  std::vector<std::string> faults;  // KIND,START_M,LENGTH_M[,MAGNITUDE], in order
  tune::LogInputOptions input;
  bool quiet = false;
};

// Refuses an --out that cannot be a file before the log is read.
void CheckOut(const std::string& out) {
  const std::filesystem::path path(out);
  if (std::filesystem::is_directory(path)) throw InputError(out, 0, "--out is a folder; give a file name");
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  if (!std::filesystem::is_directory(folder)) {
    throw InputError(out, 0, "--out: cannot write: the folder " + folder.string() + " does not exist");
  }
}

int Fault(const FaultArgs& args) {
  if (args.faults.empty()) {
    throw InputError("--fault: required, at least one KIND,START_M,LENGTH_M[,MAGNITUDE] (see slamtune fault --help)");
  }
  std::vector<sim::OdometryFault> faults;
  for (const std::string& text : args.faults) faults.push_back(sim::ParseOdometryFault(text));
  CheckOut(args.out);
  io::LaserLog log = tune::ReadLog(args.log, args.input);
  const std::vector<std::string> input = io::DescribeLogInput(log);
  tune::PrintLogInput(log, args.quiet);
  const sim::LogFaultSummary planted = sim::PlantLogFaults(log, faults);
  const std::size_t replaced = io::PrepareForCarmen(&log, /*keep_flaser=*/true);

  io::CarmenWriteOptions options;
  options.comments.push_back("odometry faults planted by slamtune into " + args.log +
                             fmt::format(", located by its odometric travel ({:.3f} m over {} robot poses in {})",
                                         planted.travel_m, planted.poses, planted.order));
  for (const sim::PlantedLogFault& fault : planted.faults) options.comments.push_back("planted: " + fault.Describe());
  for (const std::string& line : input) options.comments.push_back(line);
  options.comments.push_back(
      "readings and timestamps as recorded; laser and robot poses of every scan and every ODOM "
      "pose carry the faults; no-returns written as the max range");
  options.pose_decimals = 9;
  options.time_decimals = log.recording ? 9 : 6;  // a ROS stamp's nanoseconds, a CARMEN log's microseconds
  options.exact_ranges = true;
  const io::CarmenWriteSummary written = io::WriteCarmenLog(args.out, log, options);  // whole or not at all

  std::printf("fault: odometric travel %.3f m (%zu robot poses, %s)\n", planted.travel_m, planted.poses,
              planted.order.c_str());
  for (const sim::PlantedLogFault& fault : planted.faults) std::printf("planted %s\n", fault.Describe().c_str());
  std::printf("fault: %zu scans, %zu ODOM records%s; wrote %s\n", written.scans, written.odometry,
              replaced > 0 ? fmt::format(", {} non-finite readings written as the max range", replaced).c_str() : "",
              args.out.c_str());
  return 0;
}

const SubcommandRegistrar kFault(Subcommand{
    "fault",
    "Plant odometry faults (spin, jump, reverse) into a recorded log or bag, written as a CARMEN log with the same "
    "scans and timestamps",
    17, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<FaultArgs>();
      app.add_option("LOG", args->log, "CARMEN log (plain or gzip) or ROS 2 / ROS 1 bag")->required();
      app.add_option("--fault", args->faults,
                     "An odometry fault, KIND,START_M,LENGTH_M[,MAGNITUDE] (repeatable): spin (MAGNITUDE deg of "
                     "turn reported, not turned), jump (MAGNITUDE m of travel reported, not travelled) or reverse "
                     "(the travel reported backwards), over LENGTH_M of the log's odometric travel from START_M");
      app.add_option("--out", args->out, "CARMEN log to write (.clf)")->required();
      app.add_flag("--quiet", args->quiet, "Do not print what was read");
      AddLogInputFlags(app, args->input);
      app.footer(
          "Faults are those of `slamtune simulate --fault`, located by the distance the log's odometry\n"
          "travelled (close to the odometry path `slamtune info LOG` prints); readings and timestamps are\n"
          "kept, so the log's relations still give the error of a run.\n"
          "Examples:\n"
          "  slamtune fault intel.clf.gz --fault reverse,120,3 --out intel-reverse.clf\n"
          "  slamtune fault drive.mcap --fault spin,40,0.1,50 --fault jump,200,0.1,1 --out drive-broken.clf\n"
          "  slamtune run intel-reverse.clf --relations intel.relations --out runs/intel-reverse");
      return [args]() -> int { return Fault(*args); };
    }});

}  // namespace
}  // namespace slamtune::cli
