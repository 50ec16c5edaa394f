// `slamtune gt-error TRAJECTORY RELATIONS`: relation-based error of a trajectory against the
// Freiburg ground-truth relations (metrics/gt_error.h, tune/trajectory_error.h), as text or JSON.
#include <cstdio>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/tune/trajectory_error.h"

namespace slamtune::cli {
namespace {

struct GtErrorArgs {
  tune::TrajectoryErrorOptions options;
  bool json = false;
};

const SubcommandRegistrar kGtError(Subcommand{
    "gt-error",
    "Relation-based error (Kuemmerle et al. 2009) of a trajectory (timestamp x y theta) against "
    "ground-truth relations (t1 t2 x y z roll pitch yaw)",
    60, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<GtErrorArgs>();
      app.add_option("TRAJECTORY", args->options.trajectory, "Trajectory file: timestamp x y theta per line")
          ->required();
      app.add_option("RELATIONS", args->options.relations, "Freiburg relations file")->required();
      app.add_flag("--json", args->json, "Print the result as one JSON object");
      app.add_option("--time-tolerance", args->options.error.time_tolerance_s,
                     "Largest timestamp difference (s) for a pose to match a relation timestamp")
          ->capture_default_str();
      app.footer(
          "Examples:\n"
          "  slamtune gt-error runs/intel/trajectory.txt intel.relations\n"
          "  slamtune gt-error trajectory.txt aces.relations --json");
      return [args]() -> int {
        const metrics::GtError error = tune::TrajectoryError(args->options);
        if (args->json) {
          std::printf("%s\n", tune::ToJson(error).dump(2).c_str());
        } else {
          std::printf("%s", metrics::FormatGtError(error).c_str());
        }
        return 0;
      };
    }});

}  // namespace
}  // namespace slamtune::cli
