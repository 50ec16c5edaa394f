// `slamtune render LOG --poses TRAJECTORY|odometry --out DIR`: the occupancy map of a log drawn
// from given poses (a simulated world's truth.txt, another system's trajectory, or raw
// odometry), with its map metrics — e.g. to check that the metrics prefer the true map (the work:
// tune/pose_map_render.h).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/tune/pose_map_render.h"

namespace slamtune::cli {
namespace {

int RunRender(const tune::RenderOptions& options) {
  const tune::RenderOutcome outcome = tune::RenderAndWrite(options);
  const metrics::MapQuality& q = outcome.quality;
  std::printf("drew %d scans (%d without a pose) from %s: %dx%d cells\n", outcome.summary.scans_drawn,
              outcome.summary.scans_without_pose, options.poses.c_str(), outcome.width, outcome.height);
  std::printf("eta %.5f (known %.5f) | corner pixels %lld (%d clusters) | enclosed areas %d (%d contours)\n",
              q.occupied_ratio, q.occupied_ratio_known, static_cast<long long>(q.corner_pixels), q.corners,
              q.enclosed_areas, q.contours);
  std::printf("wrote map.pgm, map.yaml, map.png to %s\n", options.out.c_str());
  return 0;
}

const SubcommandRegistrar kRender{{
    "render",
    "Draw a log's occupancy map from given poses (a trajectory file, or 'odometry') and score it",
    35,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<tune::RenderOptions>();
      app.add_option("LOG", args->inputs.log, "CARMEN log (plain or gzip), or a ROS 2 / ROS 1 bag")->required();
      AddLogInputFlags(app, args->inputs.input);
      app.add_option("--poses", args->poses, "trajectory file (timestamp x y theta per scan) or 'odometry'")
          ->required();
      app.add_option("--out", args->out, "output folder")->required();
      AddPresetFlag(app, args->inputs.preset);
      app.add_option("--params", args->inputs.params_file,
                     "slam_toolbox or slam_karto parameter file (map resolution, laser range rules)");
      app.add_option("--set", args->inputs.sets, "NAME=VALUE override (repeatable)");
      app.footer(
          "Examples:\n"
          "  slamtune render intel.clf.gz --poses odometry --out runs/intel_odometry   # the map before SLAM\n"
          "  slamtune render intel.clf.gz --poses runs/intel/trajectory.txt --out runs/intel_again");
      return [args] { return RunRender(*args); };
    },
}};

}  // namespace
}  // namespace slamtune::cli
