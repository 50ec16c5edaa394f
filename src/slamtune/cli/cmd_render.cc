// `slamtune render LOG --poses TRAJECTORY|odometry --out DIR`: the occupancy map of a log drawn
// from given poses (a simulated world's truth.txt, another system's trajectory, or raw
// odometry), with its map metrics — e.g. to check that the metrics prefer the true map. The log
// and the base configuration are loaded as every command loads them (tune::LoadTuningInputs).
// map.pgm, map.yaml and map.png are written whole or not at all (io/map_image.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/error.h"
#include "slamtune/common/output_dir.h"
#include "slamtune/io/map_image.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/slam/pose_map.h"

namespace slamtune::cli {
namespace {

struct RenderArgs {
  tune::TuningInputOptions inputs;  // the log and the base configuration (map resolution, laser range rules)
  std::string poses, out;
};

int RunRender(const RenderArgs& args) {
  const bool odometry = args.poses == "odometry";
  std::vector<io::TimedPose> poses;
  if (!odometry) poses = io::ReadTrajectory(args.poses);  // before the log, which may take long to read
  // The one loader of every command; the output folder is checked before the log is read.
  const tune::TuningInputs inputs =
      tune::LoadTuningInputs(args.inputs, tune::InputNotes::kAll, [&args] { EnsureOutputDir(args.out); });
  const slam::MapperParams& params = inputs.base;
  const io::LaserLog& log = *inputs.log;
  if (odometry) poses = slam::OdometryTrajectory(log);
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
