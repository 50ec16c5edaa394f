// `slamtune check RECORDING`: what to know about a log or bag before tuning on it (io/check/log_check.h,
// tune/recording_check.h): its topics and choices, and each problem with its scans and times.
// Exit 0; with --strict, 1 when a problem is found; 2 for an unreadable file.
#include <cstdio>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/tune/recording_check.h"

namespace slamtune::cli {
namespace {

struct CheckArgs {
  tune::RecordingCheckOptions options;
  bool json = false;
  bool strict = false;
};

const SubcommandRegistrar kCheck(Subcommand{
    "check", "Check a log or bag before tuning: scan stamps, beams, range_max, odometry, tf, laser offset; a verdict",
    12, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<CheckArgs>();
      app.add_option("RECORDING", args->options.log, "ROS 2 / ROS 1 bag or CARMEN log")->required();
      app.add_flag("--json", args->json, "Print the report as one JSON object");
      app.add_flag("--strict", args->strict, "Exit 1 when a problem is found");
      AddLogInputFlags(app, args->options.input, MaxScansFlag::kOmit);
      io::CheckOptions& c = args->options.check;
      const char* limits = "Check limits";
      app.add_option("--gap-factor", c.gap_factor, "a scan gap is longer than this x the median period")
          ->capture_default_str()
          ->group(limits);
      app.add_option("--max-speed", c.max_speed_mps, "odometry faster than this (m/s) between samples is a jump")
          ->capture_default_str()
          ->group(limits);
      app.add_option("--stall", c.stall_s, "no odometry for this long (s) while scanning is a stall")
          ->capture_default_str()
          ->group(limits);
      app.add_option("--late", c.late_s, "odometry received this long (s) after its scan is late")
          ->capture_default_str()
          ->group(limits);
      app.footer(
          "Examples:\n"
          "  slamtune check drive.mcap\n"
          "  slamtune check drive_bag/ --scan-topic /scan_front --strict\n"
          "  slamtune check intel.clf.gz --json");
      return [args]() -> int {
        const io::CheckReport report = tune::CheckRecordingFile(args->options);
        if (args->json) {
          std::printf("%s\n", tune::ToJson(report).dump(2).c_str());
        } else {
          std::printf("%s", io::FormatCheckReport(report).c_str());
        }
        return args->strict && !report.ok() ? 1 : 0;
      };
    }});

}  // namespace
}  // namespace slamtune::cli
