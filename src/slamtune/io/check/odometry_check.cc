#include "slamtune/io/check/odometry_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/common/karto_math.h"
#include "slamtune/io/check/check_problems.h"

namespace slamtune::io {
namespace {

// A scan's index by time: the scan at or just before `time` (for listing odometry problems).
class ScanIndex {
 public:
  explicit ScanIndex(const LaserLog& log) {
    for (std::size_t k = 0; k < log.scans.size(); ++k) by_time_.emplace_back(log.scans[k].ipc_time, k);
    std::sort(by_time_.begin(), by_time_.end());
  }
  std::size_t At(double time) const {
    auto it = std::upper_bound(by_time_.begin(), by_time_.end(), std::make_pair(time, std::size_t(-1)));
    if (it == by_time_.begin()) return by_time_.empty() ? 0 : by_time_.front().second;
    return std::prev(it)->second;
  }
  std::size_t CountBetween(double a, double b) const {
    const auto lo = std::upper_bound(by_time_.begin(), by_time_.end(), std::make_pair(a, std::size_t(-1)));
    const auto hi = std::lower_bound(by_time_.begin(), by_time_.end(), std::make_pair(b, std::size_t(0)));
    return hi > lo ? static_cast<std::size_t>(hi - lo) : 0;
  }

 private:
  std::vector<std::pair<double, std::size_t>> by_time_;
};

// The odometry to check: the log's ODOM / Odometry records, or the scans' robot poses.
struct OdometryTrack {
  std::vector<OdomRecord> records;
  bool velocities = false;
  std::string source;
};

OdometryTrack TrackOf(const LaserLog& log) {
  OdometryTrack t;
  if (log.odometry.size() >= 2) {
    t.records = log.odometry;
    t.velocities = !log.recording || log.recording->odometry_velocities;
    t.source =
        log.recording ? (log.recording->odometry_velocities ? "Odometry messages" : "tf samples") : "ODOM records";
    return t;
  }
  for (const LaserScanRecord& s : log.scans) {
    OdomRecord r;
    r.pose = s.robot_pose;
    r.ipc_time = s.ipc_time;
    t.records.push_back(r);
  }
  t.source = "scan poses";
  return t;
}

}  // namespace

void CheckOdometry(const LaserLog& log, const CheckOptions& o, CheckReport* report) {
  const OdometryTrack track = TrackOf(log);
  const std::vector<OdomRecord>& r = track.records;
  if (r.size() < 2) return;
  const ScanIndex index(log);
  std::vector<double> periods;
  for (std::size_t k = 1; k < r.size(); ++k) {
    if (r[k].ipc_time > r[k - 1].ipc_time) periods.push_back(r[k].ipc_time - r[k - 1].ipc_time);
  }
  const double period = MedianOf(periods);
  report->facts.push_back(fmt::format("odometry: {} {}, median period {:.4f} s{}", r.size(), track.source, period,
                                      track.velocities ? ", with velocities" : ""));
  ProblemOccurrences jumps, wraps, gaps, frozen, mismatch;
  std::size_t moving_steps = 0, unwrapped = 0;
  double frozen_since = -1.0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    const OdomRecord &a = r[k - 1], &b = r[k];
    const double dt = b.ipc_time - a.ipc_time;
    const double d = std::hypot(b.pose.x - a.pose.x, b.pose.y - a.pose.y);
    const double turn = std::fabs(NormalizeAngle(b.pose.theta - a.pose.theta));
    const std::size_t scan = index.At(b.ipc_time);
    if (std::fabs(b.pose.theta) > kPi + 1e-6) ++unwrapped;
    const bool wrapped = std::fabs(b.pose.theta - a.pose.theta) > kPi;
    if (wrapped && std::min(std::fabs(a.pose.theta), std::fabs(b.pose.theta)) < kPi / 2) {
      wraps.Add(scan, b.ipc_time);
    } else if ((dt <= 0 && (d > 0.05 || turn > 0.05)) ||
               (dt > 0 &&
                ((d > 0.1 && d / dt > o.max_speed_mps) || (turn > 0.2 && turn / dt > o.max_turn_rate_rad_s)))) {
      jumps.Add(scan, b.ipc_time);
    }
    if (track.source != "scan poses" && period > 0 && period < o.stall_s / 2 && dt > o.stall_s &&
        index.CountBetween(a.ipc_time, b.ipc_time) > 0) {
      gaps.Add(scan, a.ipc_time);
    }
    if (!track.velocities || dt <= 0) continue;
    const double v = 0.5 * (a.tv + b.tv);
    const bool still = d < 1e-9 && turn < 1e-9;
    if (std::fabs(v) > o.moving_speed_mps && still) {
      if (frozen_since < 0) frozen_since = a.ipc_time;
      if (b.ipc_time - frozen_since > o.stall_s && (frozen.count == 0 || frozen.times.back() != frozen_since)) {
        frozen.Add(index.At(frozen_since), frozen_since);
      }
    } else {
      frozen_since = -1.0;
    }
    const double forward =
        std::cos(a.pose.theta) * (b.pose.x - a.pose.x) + std::sin(a.pose.theta) * (b.pose.y - a.pose.y);
    if (std::fabs(v) > o.moving_speed_mps && std::fabs(forward) > 1e-3) {
      ++moving_steps;
      if ((forward > 0) != (v > 0)) mismatch.Add(scan, b.ipc_time);
    }
  }
  if (unwrapped > 0) report->facts.push_back(fmt::format("headings: {} outside [-pi, pi] (not wrapped)", unwrapped));
  ReportOccurrences(
      report, ProblemKind::kOdometryJump, jumps,
      fmt::format("{} odometry jumps (faster than {} m/s or {} rad/s between samples, or a move within one stamp)",
                  jumps.count, o.max_speed_mps, o.max_turn_rate_rad_s));
  ReportOccurrences(report, ProblemKind::kHeadingWrap, wraps,
                    fmt::format("{} heading wraps away from +-pi (a step of more than pi between headings near 0): the "
                                "odometry heading is discontinuous",
                                wraps.count));
  ProblemOccurrences stalls = gaps;
  for (std::size_t k = 0; k < frozen.scans.size(); ++k) stalls.Add(frozen.scans[k], frozen.times[k]);
  stalls.count = gaps.count + frozen.count;
  ReportOccurrences(
      report, ProblemKind::kOdometryStall, stalls,
      fmt::format("odometry stalls: {} gaps of more than {} s while scans go on, {} times the pose frozen for more "
                  "than {} s while the recorded speed says moving",
                  gaps.count, o.stall_s, frozen.count, o.stall_s));
  if (moving_steps > 0 && static_cast<double>(mismatch.count) > o.velocity_mismatch_share * moving_steps) {
    ReportOccurrences(
        report, ProblemKind::kOdometryVelocityMismatch, mismatch,
        fmt::format("odometry poses disagree with the recorded velocities in {} of {} moving steps: the pose moves "
                    "forward while the speed is negative or the other way round (a logger that integrated |tv| "
                    "turns reversing into driving forward); the map will break whatever the SLAM parameters",
                    mismatch.count, moving_steps));
  }
}

}  // namespace slamtune::io
