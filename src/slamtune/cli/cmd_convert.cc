// `slamtune convert RECORDING --out FILE.clf`: what slamtune read from a log or bag, written as a
// CARMEN log (ROBOTLASER1 lines with the laser and the robot pose, ODOM lines, the laser offset
// and max range as PARAMs; the work: tune/carmen_export.h), so that other tools read exactly the
// scans slamtune reads. A no-return written as +inf or NaN in the recording is written as the
// scan's max range (the CARMEN convention), and counted.
#include <cstdio>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/tune/carmen_export.h"

namespace slamtune::cli {
namespace {

const SubcommandRegistrar kConvert(Subcommand{
    "convert", "Write what slamtune reads from a log or bag as a CARMEN log (ROBOTLASER1 with laser and robot poses)",
    15, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<tune::ConvertOptions>();
      app.add_option("RECORDING", args->log, "ROS 2 / ROS 1 bag (or a CARMEN log)")->required();
      AddCarmenOutputFlags(app, args->out, args->quiet, args->input);
      app.footer(
          "Examples:\n"
          "  slamtune convert drive.mcap --out drive.clf\n"
          "  slamtune convert drive_bag/ --scan-topic /scan_front --base-frame base_link --out drive.clf");
      return [args]() -> int {
        const tune::CarmenExport exported = tune::ConvertToCarmen(*args);
        std::printf("convert: %s\n", tune::DescribeExport(exported, args->out).c_str());
        return 0;
      };
    }});

}  // namespace
}  // namespace slamtune::cli
