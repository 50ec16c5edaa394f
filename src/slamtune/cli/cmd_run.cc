// `slamtune run LOG --out DIR`: one Karto SLAM run of a log or bag (tune/single_run.h) with
// the map (map.pgm + map.yaml as map_saver writes them, map.png), the trajectory of every log
// scan, the loop closures, the front end's matches, and run.json (counts, timing, parameters,
// map metrics and, with --relations, the Freiburg relation error). Without LOG it runs on a
// built-in world simulated in memory (`--world`, `--world-seed`, as `optimize` does), and the
// world's relations give the error against its true trajectory unless --relations names others.
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/progress.h"
#include "slamtune/tune/single_run.h"

namespace slamtune::cli {
namespace {

void PrintRunSummary(const slam::RunSummary& summary, slam::NodeMode mode, const std::string& gt_line,
                     const std::string& out, const slam::FrontEndEvidence& front_end) {
  const std::string dropped = summary.scans_wrong_reading_count > 0
                                  ? fmt::format(", {} scans dropped (reading count differs from the first scan's)",
                                                summary.scans_wrong_reading_count)
                                  : "";
  std::printf("run: %d scans, %d nodes, %zu loop closures, %d edges, %.1f s wall%s%s%s; wrote %s\n", summary.scans_read,
              summary.nodes, summary.loop_closures.size(), summary.total_edges(), summary.wall_s,
              tune::NodeRefusalsText(summary, mode).c_str(), dropped.c_str(), gt_line.c_str(), out.c_str());
  std::printf("%s\n", front_end.Summary().c_str());
  if (front_end.points_at_front_end()) {
    std::printf(
        "  (front_end_map.png marks them on the map, front_end.csv has every match; the default "
        "optimize searches the front-end parameters for this log)\n");
  }
}

int Run(const tune::RunOptions& options) {
  Progress progress(options.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto, 10.0);
  const tune::RunOutcome outcome = tune::RunAndWrite(options, progress);
  progress.Finish();
  const optim::SlamRun& run = outcome.run;
  PrintRunSummary(run.summary, outcome.node_mode, tune::RelationErrorText(outcome.error), options.out, run.front_end);
  const std::string lasers = tune::LasersText(run.lasers, run.summary);
  if (!lasers.empty()) std::printf("%s\n", lasers.c_str());
  return 0;
}

const SubcommandRegistrar kRun(Subcommand{
    "run",
    "Run the Karto-faithful SLAM engine on a log or bag: map.pgm/map.yaml/map.png, trajectory.txt, "
    "loop_closures.csv, front_end.csv, front_end_map.png and run.json in --out",
    20, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<tune::RunOptions>();
      tune::TuningInputOptions& inputs = args->inputs;
      app.add_option("LOG", inputs.log,
                     "CARMEN log (plain or gzip), or a ROS 2 / ROS 1 bag; none: the built-in world --world");
      app.add_option("--out", args->out, "Output folder (created)")->required();
      app.add_option("--params", inputs.params_file,
                     "your slam_toolbox (ROS 2) or slam_karto (flat) parameter file, or a best.yaml that optimize "
                     "wrote; keys it does not set take that node's own defaults");
      AddPresetFlag(app, inputs.preset);
      app.add_option("--set", inputs.sets, "Override one parameter, name=value (repeatable; applied last)");
      app.add_option("--relations", inputs.relations, "Freiburg relations file: report the relation error");
      app.add_option("--world", inputs.world, "built-in world to simulate when no LOG is given (see `simulate --list`)")
          ->capture_default_str();
      app.add_option("--world-seed", inputs.world_seed, "seed of the simulated world")->capture_default_str();
      app.add_flag("--no-loop-closure", args->no_loop_closure, "Same as --set do_loop_closing=false");
      app.add_option("--trace", args->trace,
                     "Write every scan match and back-end solve to FILE at full precision (docs/trace.md)");
      AddLogInputFlags(app, inputs.input);
      app.add_flag("--quiet", args->quiet, "No progress on stderr");
      app.footer(
          "Examples:\n"
          "  slamtune run drive.mcap --out runs/drive_defaults\n"
          "  slamtune run drive.mcap --out runs/drive_best --params runs/drive/best.yaml\n"
          "  slamtune run intel.clf.gz --relations intel.relations --set loop_search_maximum_distance=6 --out "
          "runs/intel_r6\n"
          "  slamtune run --world corridor-long --out runs/corridor   # a built-in world, error against its truth");
      return [args]() -> int { return Run(*args); };
    }});

}  // namespace
}  // namespace slamtune::cli
