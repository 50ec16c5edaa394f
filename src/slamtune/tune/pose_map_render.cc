#include "slamtune/tune/pose_map_render.h"

#include <filesystem>

#include "slamtune/common/output_dir.h"
#include "slamtune/io/map_image.h"

namespace slamtune::tune {

RenderOutcome RenderAndWrite(const RenderOptions& options) {
  const bool odometry = options.poses == kOdometryPoses;
  std::vector<io::TimedPose> poses;
  if (!odometry) poses = io::ReadTrajectory(options.poses);  // before the log, which may take long to read
  // The one loader of every command; the output folder is checked before the log is read.
  const TuningInputs inputs =
      LoadTuningInputs(options.inputs, InputNotes::kAll, [&options] { EnsureOutputDir(options.out); });
  if (odometry) poses = slam::OdometryTrajectory(*inputs.log);
  RenderOutcome out;
  const io::MapImage map = slam::MapFromPoses(*inputs.log, poses, inputs.base, &out.summary);
  io::WriteMapServer(map, (std::filesystem::path(options.out) / "map.yaml").string());
  io::WritePng(map, (std::filesystem::path(options.out) / "map.png").string());
  out.width = map.width;
  out.height = map.height;
  out.quality = metrics::ComputeMapQuality(map);
  return out;
}

}  // namespace slamtune::tune
