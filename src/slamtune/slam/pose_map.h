// Occupancy map of a log drawn from given poses rather than from a SLAM run: the true
// trajectory of a simulated world, raw odometry, or another system's trajectory. Uses the
// engine's own laser geometry (log_runner.h) and occupancy grid (occupancy_grid.h, docs/engine.md §8),
// so maps from poses and maps from SLAM runs are directly comparable under the metrics.
#pragma once

#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/map_image.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {

struct PoseMapSummary {
  int scans_drawn = 0;
  int scans_without_pose = 0;  // log scans whose timestamp is not in the trajectory
};

// Draws every log scan at its pose in `poses` (laser poses, matched by timestamp within
// 1e-5 s). Throws InputError when no scan has a pose.
io::MapImage MapFromPoses(const io::LaserLog& log, const std::vector<io::TimedPose>& poses, const MapperParams& params,
                          PoseMapSummary* summary = nullptr);

// The log's own odometric laser poses as a trajectory (what the map looks like with no
// correction at all).
std::vector<io::TimedPose> OdometryTrajectory(const io::LaserLog& log);

}  // namespace slamtune::slam
