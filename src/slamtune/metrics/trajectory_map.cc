#include "slamtune/metrics/trajectory_map.h"

#include <fmt/format.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/slam/log_runner.h"

namespace slamtune::metrics {

void TrajectoryMapOptions::Validate() const {
  const auto check = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0) {
      throw InputError("", 0, fmt::format("trajectory map: {} must be finite and >= 0 (got {})", name, v));
    }
  };
  check(min_travel_m, "min_travel_m");
  check(min_turn_rad, "min_turn_rad");
}

TrajectoryMap::TrajectoryMap(std::shared_ptr<const io::LaserLog> log, const slam::MapperParams& base,
                             const TrajectoryMapOptions& options)
    : log_(std::move(log)) {
  SLAMTUNE_CHECK(log_ != nullptr);
  options.Validate();
  if (log_->scans.empty()) return;
  const slam::OdometryFrame frame = slam::OdometryFrameOf(*log_);
  lasers_ = std::make_shared<const slam::LogLasers>(slam::LasersOf(*log_, base, frame));
  grid_ = slam::GridOptionsOf(base);
  const Pose2* last = nullptr;
  for (std::size_t i = 0; i < log_->scans.size(); ++i) {
    const io::LaserScanRecord& record = log_->scans[i];
    if (static_cast<int>(record.ranges.size()) != lasers_->geometries[lasers_->LaserOf(i)]->num_readings) continue;
    const Pose2& odom = slam::OdometricPose(record, frame);
    if (last != nullptr) {
      const double travel = std::hypot(odom.x - last->x, odom.y - last->y);
      const double turn = std::fabs(NormalizeAngle(odom.theta - last->theta));
      if (travel < options.min_travel_m && turn < options.min_turn_rad) continue;
    }
    last = &odom;
    indices_.push_back(i);
  }
}

slam::OccupancyGrid TrajectoryMap::Draw(std::span<const io::TimedPose> trajectory) const {
  SLAMTUNE_CHECK(trajectory.size() == log_->scans.size());
  std::vector<slam::LaserScan> scans;
  scans.reserve(indices_.size());
  for (const std::size_t i : indices_) {
    const io::LaserScanRecord& record = log_->scans[i];
    std::shared_ptr<const std::vector<double>> ranges(log_, &record.ranges);
    slam::LaserScan scan(lasers_->geometries[lasers_->LaserOf(i)], ranges, trajectory[i].pose, record.ipc_time);
    scan.SetSensorPose(trajectory[i].pose);
    scans.push_back(std::move(scan));
  }
  return slam::OccupancyGrid::FromScans(std::span<const slam::LaserScan>(scans), grid_);
}

}  // namespace slamtune::metrics
