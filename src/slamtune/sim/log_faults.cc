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

// A pose of the path as the log has it.
const Pose2& OriginalPathPose(const io::LaserLog& log, const PathPose& p) {
  return p.scan ? log.scans[p.index].robot_pose : log.odometry[p.index].pose;
}

// Odometric travel at every pose of the path.
std::vector<double> OdometricTravel(const io::LaserLog& log, const std::vector<PathPose>& path) {
  std::vector<double> travel(path.size(), 0.0);
  for (std::size_t k = 1; k < path.size(); ++k) {
    const Pose2 &a = OriginalPathPose(log, path[k - 1]), &b = OriginalPathPose(log, path[k]);
    travel[k] = travel[k - 1] + std::hypot(b.x - a.x, b.y - a.y);
  }
  return travel;
}

// One PlantedLogFault per fault, in the order given; throws when a stretch ends beyond the log's travel.
std::vector<PlantedLogFault> FaultsWithinTravel(const io::LaserLog& log, const std::vector<OdometryFault>& faults,
                                                double travel_m) {
  std::vector<PlantedLogFault> planted_faults;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    const double end = faults[i].start_m + faults[i].length_m;
    if (!(end <= travel_m)) {
      throw InputError(log.path, 0,
                       fmt::format("fault {} ({}): its stretch ends at {:.6g} m, beyond the log's odometric travel "
                                   "of {:.6g} m",
                                   i + 1, faults[i].Describe(), end, travel_m));
    }
    PlantedLogFault planted;
    planted.fault = faults[i];
    planted_faults.push_back(planted);
  }
  return planted_faults;
}

// The faulted robot pose at every pose of the path, and whether it differs from the original.
struct FaultedPath {
  std::vector<Pose2> poses;
  std::vector<bool> changed;
};

// Where `planted` fell, updated at pose k of the path with its faulted pose and the displacement so far.
void NoteFaultAtStep(const io::LaserLog& log, const std::vector<PathPose>& path, const std::vector<double>& travel,
                     std::size_t k, const Pose2& faulted, const Pose2& displacement, PlantedLogFault& planted) {
  const OdometryFault& fault = planted.fault;
  const double from = travel[k - 1], distance = travel[k] - travel[k - 1];
  const bool within = FaultEffectOnStep({fault}, from, distance).active;
  if (path[k].scan && travel[k] > fault.start_m && !planted.first_scan) {
    planted.first_scan = path[k].index;
    planted.first_time = log.scans[path[k].index].ipc_time - log.scans.front().ipc_time;
  }
  if (path[k].scan && travel[k] > fault.start_m && travel[k] <= fault.start_m + fault.length_m) {
    ++planted.scans_within;
  }
  if (within && travel[k] >= fault.start_m + fault.length_m) {
    const Pose2& original = OriginalPathPose(log, path[k]);
    planted.displacement = displacement;
    planted.shift_m = std::hypot(faulted.x - original.x, faulted.y - original.y);
    planted.turn_rad = NormalizeAngle(faulted.theta - original.theta);
  }
}

// The faulted robot pose at every pose of the path: unchanged until the first fault, composed
// step by step where a fault acts, the original moved by one rigid transform in between. Notes
// where each fault fell in `planted` (one per fault).
FaultedPath FaultedPathOf(const io::LaserLog& log, const std::vector<PathPose>& path, const std::vector<double>& travel,
                          const std::vector<OdometryFault>& faults, std::vector<PlantedLogFault>& planted) {
  const std::size_t n = path.size();
  const auto original = [&](std::size_t k) -> const Pose2& { return OriginalPathPose(log, path[k]); };
  FaultedPath out{std::vector<Pose2>(n), std::vector<bool>(n, false)};
  std::vector<Pose2>& faulted = out.poses;
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
    out.changed[k] = displaced;
    for (PlantedLogFault& p : planted) NoteFaultAtStep(log, path, travel, k, faulted[k], displacement, p);
  }
  return out;
}

// Writes the changed poses into the log; laser poses follow their robot poses.
void WriteFaultedPath(const std::vector<PathPose>& path, const FaultedPath& faulted, io::LaserLog& log) {
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (!faulted.changed[k]) continue;
    if (path[k].scan) {
      io::LaserScanRecord& scan = log.scans[path[k].index];
      scan.robot_pose = faulted.poses[k];
      scan.laser_pose = Compose(faulted.poses[k], scan.laser_offset);
    } else {
      log.odometry[path[k].index].pose = faulted.poses[k];
    }
  }
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
  const std::vector<double> travel = OdometricTravel(log, path);
  summary.travel_m = travel.back();
  summary.faults = FaultsWithinTravel(log, faults, summary.travel_m);
  const FaultedPath faulted = FaultedPathOf(log, path, travel, faults, summary.faults);
  WriteFaultedPath(path, faulted, log);
  return summary;
}

}  // namespace slamtune::sim
