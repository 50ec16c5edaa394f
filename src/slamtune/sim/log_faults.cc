#include "slamtune/sim/log_faults.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

// One robot pose of the odometric path: an ODOM record's or a scan's.
struct PathPose {
  bool scan = false;
  std::size_t index = 0;  // into log.scans or log.odometry
};

// Every robot pose of the log in file order (a CARMEN log whose records all have a line) or in
// time order (a ROS recording, or a log made in memory), ODOM records first at equal keys.
std::vector<PathPose> OdometricPath(const io::LaserLog& log, std::string* order) {
  std::vector<PathPose> path;
  path.reserve(log.odometry.size() + log.scans.size());
  for (std::size_t i = 0; i < log.odometry.size(); ++i) path.push_back({false, i});
  for (std::size_t i = 0; i < log.scans.size(); ++i) path.push_back({true, i});
  const auto line = [&](const PathPose& p) { return p.scan ? log.scans[p.index].line : log.odometry[p.index].line; };
  const auto time = [&](const PathPose& p) {
    return p.scan ? log.scans[p.index].ipc_time : log.odometry[p.index].ipc_time;
  };
  const bool file_order =
      !log.recording && std::all_of(path.begin(), path.end(), [&](const PathPose& p) { return line(p) > 0; });
  if (file_order) {
    std::stable_sort(path.begin(), path.end(), [&](const PathPose& a, const PathPose& b) { return line(a) < line(b); });
  } else {
    std::stable_sort(path.begin(), path.end(), [&](const PathPose& a, const PathPose& b) { return time(a) < time(b); });
  }
  *order = file_order ? "file order" : "time order";
  return path;
}

}  // namespace

std::string PlantedLogFault::Describe() const {
  const std::string where = first_scan ? fmt::format("from scan {} ({:.1f} s into the log), {} scans within",
                                                     *first_scan, first_time, scans_within)
                                       : std::string("after the last scan");
  return fmt::format("{}: {}; odometry after it {:.3f} m and {:.1f} deg off", fault.Describe(), where, shift_m,
                     RadToDeg(turn_rad));
}

LogFaultSummary PlantLogFaults(io::LaserLog& log, const std::vector<OdometryFault>& faults) {
  for (std::size_t i = 0; i < faults.size(); ++i) faults[i].Validate(fmt::format("fault {}", i + 1));
  LogFaultSummary summary;
  const std::vector<PathPose> path = OdometricPath(log, &summary.order);
  const std::size_t n = path.size();
  summary.poses = n;
  if (n < 2) {
    throw InputError(log.path, 0,
                     fmt::format("{} robot poses (scans and ODOM records): a fault needs an odometric path", n));
  }
  const auto original = [&](std::size_t k) -> const Pose2& {
    return path[k].scan ? log.scans[path[k].index].robot_pose : log.odometry[path[k].index].pose;
  };
  // Odometric travel at every pose of the path.
  std::vector<double> travel(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) {
    const Pose2 &a = original(k - 1), &b = original(k);
    travel[k] = travel[k - 1] + std::hypot(b.x - a.x, b.y - a.y);
  }
  summary.travel_m = travel.back();
  for (std::size_t i = 0; i < faults.size(); ++i) {
    const double end = faults[i].start_m + faults[i].length_m;
    if (!(end <= summary.travel_m)) {
      throw InputError(log.path, 0,
                       fmt::format("fault {} ({}): its stretch ends at {:.6g} m, beyond the log's odometric travel "
                                   "of {:.6g} m",
                                   i + 1, faults[i].Describe(), end, summary.travel_m));
    }
    PlantedLogFault planted;
    planted.fault = faults[i];
    summary.faults.push_back(planted);
  }

  // The faulted robot pose at every pose of the path: unchanged until the first fault, composed
  // step by step where a fault acts, the original moved by one rigid transform in between.
  std::vector<Pose2> faulted(n);
  std::vector<bool> changed(n, false);
  faulted[0] = original(0);
  Pose2 displacement;
  bool displaced = false;
  for (std::size_t k = 1; k < n; ++k) {
    const double from = travel[k - 1], distance = travel[k] - travel[k - 1];
    const FaultEffect effect = FaultEffectOnStep(faults, from, distance);
    if (effect.active) {
      Pose2 step = Between(original(k - 1), original(k));
      const double scale = (distance + effect.extra_distance) / distance;  // active only when distance > 0
      step.x *= scale;
      step.y *= scale;
      step.theta = NormalizeAngle(step.theta + effect.extra_rotation);
      faulted[k] = Compose(faulted[k - 1], step);
      displacement = Compose(faulted[k], Inverse(original(k)));
      displaced = true;
    } else {
      faulted[k] = displaced ? Compose(displacement, original(k)) : original(k);
    }
    changed[k] = displaced;
    for (std::size_t i = 0; i < faults.size(); ++i) {
      PlantedLogFault& planted = summary.faults[i];
      const OdometryFault& fault = faults[i];
      const bool within = FaultEffectOnStep({fault}, from, distance).active;
      if (path[k].scan && travel[k] > fault.start_m && !planted.first_scan) {
        planted.first_scan = path[k].index;
        planted.first_time = log.scans[path[k].index].ipc_time - log.scans.front().ipc_time;
      }
      if (path[k].scan && travel[k] > fault.start_m && travel[k] <= fault.start_m + fault.length_m) {
        ++planted.scans_within;
      }
      if (within && travel[k] >= fault.start_m + fault.length_m) {
        planted.displacement = displacement;
        planted.shift_m = std::hypot(faulted[k].x - original(k).x, faulted[k].y - original(k).y);
        planted.turn_rad = NormalizeAngle(faulted[k].theta - original(k).theta);
      }
    }
  }

  for (std::size_t k = 0; k < n; ++k) {
    if (!changed[k]) continue;
    if (path[k].scan) {
      io::LaserScanRecord& scan = log.scans[path[k].index];
      scan.robot_pose = faulted[k];
      scan.laser_pose = Compose(faulted[k], scan.laser_offset);
    } else {
      log.odometry[path[k].index].pose = faulted[k];
    }
  }
  return summary;
}

}  // namespace slamtune::sim
