#include "slamtune/slam/pose_map.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "slamtune/common/error.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/occupancy_grid.h"

namespace slamtune::slam {

std::vector<io::TimedPose> OdometryTrajectory(const io::LaserLog& log) {
  std::vector<io::TimedPose> out;
  out.reserve(log.scans.size());
  for (const auto& s : log.scans) out.push_back({s.ipc_time, s.laser_pose});
  return out;
}

io::MapImage MapFromPoses(const io::LaserLog& log, const std::vector<io::TimedPose>& poses, const MapperParams& params,
                          PoseMapSummary* summary) {
  params.Validate();
  std::vector<io::TimedPose> sorted = poses;
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
  PoseMapSummary local;
  std::vector<LaserScan> scans;
  scans.reserve(log.scans.size());
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const auto& record = log.scans[i];
    auto it = std::lower_bound(sorted.begin(), sorted.end(), record.ipc_time - 1e-5,
                               [](const io::TimedPose& p, double t) { return p.time < t; });
    if (it == sorted.end() || std::fabs(it->time - record.ipc_time) > 1e-5) {
      ++local.scans_without_pose;
      continue;
    }
    auto geometry = std::make_shared<const LaserGeometry>(GeometryForRecord(record, params));
    auto ranges = std::make_shared<const std::vector<double>>(record.ranges);
    LaserScan scan(geometry, ranges, record.laser_pose, record.ipc_time);
    scan.log_index = static_cast<int>(i);
    scan.SetSensorPose(it->pose);
    scans.push_back(std::move(scan));
  }
  local.scans_drawn = static_cast<int>(scans.size());
  if (summary) *summary = local;
  if (scans.empty()) {
    throw InputError(log.path, 0, "no scan of the log has a pose in the trajectory (timestamps differ)");
  }
  return OccupancyGrid::FromScans(std::span<const LaserScan>(scans), GridOptionsOf(params)).ToMapImage();
}

}  // namespace slamtune::slam
