// `slamtune info LOG`: what a log holds (io/log_summary.h) — a CARMEN log or a ROS recording —
// as a table or JSON (tune/log_info.h).
#include <cstdio>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/tune/log_info.h"

namespace slamtune::cli {
namespace {

struct InfoArgs {
  tune::LogInfoOptions options;
  bool json = false;
};

const SubcommandRegistrar kInfo(Subcommand{
    "info",
    "Summarise a log (CARMEN, or a ROS 2 / ROS 1 bag): scans, beam geometry, no-return value, odometry, "
    "laser offset, time-order anomalies",
    10, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<InfoArgs>();
      app.add_option("LOG", args->options.log,
                     "CARMEN log (.clf, plain or gzip), MCAP / .db3 / rosbag2 folder, or ROS 1 .bag")
          ->required();
      app.add_flag("--json", args->json, "Print the summary as one JSON object");
      AddLogInputFlags(app, args->options.input);
      app.footer(
          "Examples:\n"
          "  slamtune info intel.clf.gz\n"
          "  slamtune info drive.mcap --scan-topic /scan --json");
      return [args]() -> int {
        const io::LogSummary summary = tune::SummarizeLogFile(args->options);
        if (args->json) {
          std::printf("%s\n", tune::ToJson(summary).dump(2).c_str());
        } else {
          std::printf("%s", io::FormatLogSummary(summary).c_str());
        }
        return 0;
      };
    }});

}  // namespace
}  // namespace slamtune::cli
