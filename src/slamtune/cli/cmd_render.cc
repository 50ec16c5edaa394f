// `slamtune render LOG --poses TRAJECTORY|odometry --out DIR`: the occupancy map of a log drawn
// from given poses (a simulated world's truth.txt, another system's trajectory, or raw
// odometry), with its map metrics — e.g. to check that the metrics prefer the true map.
// map.pgm, map.yaml and map.png are written whole or not at all (io/map_image.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/error.h"
#include "slamtune/common/output_dir.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/map_image.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/slam/base_configuration.h"
#include "slamtune/slam/pose_map.h"

namespace slamtune::cli {
namespace {

struct RenderArgs {
  std::string log, poses, out, preset, params_file;
  tune::LogInputOptions input;
  std::vector<std::string> sets;
};

int RunRender(const RenderArgs& args) {
  const slam::BaseConfiguration base = slam::LoadBaseConfiguration(args.params_file, args.preset, args.sets);
  tune::PrintParamsWarnings(base);
  const slam::MapperParams& params = base.params;
  EnsureOutputDir(args.out);  // before the work
  const io::LaserLog log = tune::ReadLog(args.log, args.input);
  for (const std::string& line : io::DescribeLogInput(log)) std::fprintf(stderr, "%s\n", line.c_str());
  const auto poses = args.poses == "odometry" ? slam::OdometryTrajectory(log) : io::ReadTrajectory(args.poses);
  slam::PoseMapSummary summary;
  const io::MapImage map = slam::MapFromPoses(log, poses, params, &summary);
  io::WriteMapServer(map, (std::filesystem::path(args.out) / "map.yaml").string());
  io::WritePng(map, (std::filesystem::path(args.out) / "map.png").string());
  const metrics::MapQuality q = metrics::ComputeMapQuality(map);
  std::printf("drew %d scans (%d without a pose) from %s: %dx%d cells\n", summary.scans_drawn,
              summary.scans_without_pose, args.poses.c_str(), map.width, map.height);
  std::printf("eta %.5f (known %.5f) | corner pixels %lld (%d clusters) | enclosed areas %d (%d contours)\n",
              q.occupied_ratio, q.occupied_ratio_known, static_cast<long long>(q.corner_pixels), q.corners,
              q.enclosed_areas, q.contours);
  std::printf("wrote map.pgm, map.yaml, map.png to %s\n", args.out.c_str());
  return 0;
}

const SubcommandRegistrar kRender{{
    "render",
    "Draw a log's occupancy map from given poses (a trajectory file, or 'odometry') and score it",
    35,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<RenderArgs>();
      app.add_option("LOG", args->log, "CARMEN log (plain or gzip), or a ROS 2 / ROS 1 bag")->required();
      AddLogInputFlags(app, args->input);
      app.add_option("--poses", args->poses, "trajectory file (timestamp x y theta per scan) or 'odometry'")
          ->required();
      app.add_option("--out", args->out, "output folder")->required();
      AddPresetFlag(app, args->preset);
      app.add_option("--params", args->params_file,
                     "slam_toolbox or slam_karto parameter file (map resolution, laser range rules)");
      app.add_option("--set", args->sets, "NAME=VALUE override (repeatable)");
      app.footer(
          "Examples:\n"
          "  slamtune render intel.clf.gz --poses odometry --out runs/intel_odometry   # the map before SLAM\n"
          "  slamtune render intel.clf.gz --poses runs/intel/trajectory.txt --out runs/intel_again");
      return [args] { return RunRender(*args); };
    },
}};

}  // namespace
}  // namespace slamtune::cli
