// `slamtune fault LOG --fault KIND,START_M,LENGTH_M[,MAGNITUDE] --out OUT.clf`: a recording with
// planted odometry failures, written as a CARMEN log (the work: tune/carmen_export.h), so that a
// tuner's repair of a broken front end can be measured on real scans against the recording's own
// relations. Faults take the form and meaning of `simulate --fault` (sim/odometry_fault.h),
// located by the log's odometric travel; the scans' readings and timestamps are kept.
#include <cstdio>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/tune/carmen_export.h"

namespace slamtune::cli {
namespace {

int Fault(const tune::FaultOptions& options) {
  const tune::FaultOutcome outcome = tune::PlantFaultsAndWrite(options);
  const sim::LogFaultSummary& planted = outcome.planted;
  std::printf("fault: odometric travel %.3f m (%zu robot poses, %s)\n", planted.travel_m, planted.poses,
              planted.order.c_str());
  for (const sim::PlantedLogFault& fault : planted.faults) std::printf("planted %s\n", fault.Describe().c_str());
  std::printf("fault: %s\n", tune::DescribeExport(outcome.exported, options.out).c_str());
  return 0;
}

const SubcommandRegistrar kFault(Subcommand{
    "fault",
    "Plant odometry faults (spin, jump, reverse) into a recorded log or bag, written as a CARMEN log with the same "
    "scans and timestamps",
    17, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<tune::FaultOptions>();
      app.add_option("LOG", args->log, "CARMEN log (plain or gzip) or ROS 2 / ROS 1 bag")->required();
      app.add_option("--fault", args->faults,
                     "An odometry fault, KIND,START_M,LENGTH_M[,MAGNITUDE] (repeatable): spin (MAGNITUDE deg of "
                     "turn reported, not turned), jump (MAGNITUDE m of travel reported, not travelled) or reverse "
                     "(the travel reported backwards), over LENGTH_M of the log's odometric travel from START_M");
      AddCarmenOutputFlags(app, args->out, args->quiet, args->input);
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
