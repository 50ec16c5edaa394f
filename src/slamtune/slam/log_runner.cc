#include "slamtune/slam/log_runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"

namespace slamtune::slam {

int RunSummary::total_edges() const { return std::accumulate(edges.begin(), edges.end(), 0); }

int RunSummary::scans_refused_by_node_total() const {
  return std::accumulate(scans_refused_by_node.begin(), scans_refused_by_node.end(), 0);
}

OdometryFrame OdometryFrameOf(const io::LaserLog& log) {
  OdometryFrame frame;
  if (log.scans.empty()) return frame;
  const Pose2 first = log.scans.front().laser_offset;
  for (const io::LaserScanRecord& s : log.scans) {
    const Pose2& o = s.laser_offset;
    if (!(std::fabs(o.x - first.x) <= kSameOffsetTolerance && std::fabs(o.y - first.y) <= kSameOffsetTolerance &&
          std::fabs(NormalizeAngle(o.theta - first.theta)) <= kSameOffsetTolerance)) {
      return frame;  // not a fixed mount: laser poses, zero offset
    }
  }
  frame.robot_poses = true;
  frame.offset = first;
  return frame;
}

LaserGeometry GeometryForRecord(const io::LaserScanRecord& record, const MapperParams& params, const Pose2& offset) {
  LaserGeometry g;
  g.min_angle = record.angle_min;
  g.angular_resolution = record.angle_increment;
  g.num_readings = static_cast<int>(record.ranges.size());
  g.min_range = params.min_laser_range;
  // §2.3: the value a driver writes for "no return" is the laser's range_max, capped as in the
  // reference setup (80 m); a log without one uses the cap.
  g.max_range = std::min(params.laser_max_range_cap, record.max_range);
  g.range_threshold = params.RangeThreshold(g.min_range, g.max_range);
  g.offset = offset;  // the laser's offset pose (§1.4; zero for laser poses as odometry)
  return g;
}

namespace {

// "laser_7", zero-padded to the width of the largest index so that names sort in index order.
std::string LaserName(std::size_t index, std::size_t count) {
  const std::size_t width = fmt::formatted_size("{}", count > 1 ? count - 1 : 0);
  return fmt::format("laser_{:0{}}", index, width);
}

}  // namespace

LogLasers LasersOf(const io::LaserLog& log, const MapperParams& params, const OdometryFrame& frame) {
  LogLasers lasers;
  if (log.scans.empty()) return lasers;
  const auto make = [&](const io::LaserScanRecord& record) {
    lasers.geometries.push_back(std::make_shared<const LaserGeometry>(GeometryForRecord(record, params, frame.offset)));
  };
  if (log.beams.policy != io::BeamPolicyName(io::BeamPolicy::kPerGeometry)) {
    make(log.scans.front());
  } else {
    std::vector<io::BeamGeometry> seen;
    lasers.laser_of_scan.reserve(log.scans.size());
    for (const io::LaserScanRecord& record : log.scans) {
      const io::BeamGeometry g = io::GeometryOf(record);
      auto it = std::find_if(seen.begin(), seen.end(),
                             [&](const io::BeamGeometry& s) { return s.SameAs(g, io::kSameAngleTolerance); });
      if (it == seen.end()) {
        seen.push_back(g);
        make(record);
        it = seen.end() - 1;
      }
      lasers.laser_of_scan.push_back(static_cast<int>(it - seen.begin()));
    }
  }
  for (std::size_t k = 0; k < lasers.geometries.size(); ++k) {
    lasers.names.push_back(LaserName(k, lasers.geometries.size()));
  }
  return lasers;
}

LogRunner::LogRunner(std::shared_ptr<const io::LaserLog> log, const MapperParams& params, SharedWork shared)
    : log_(std::move(log)), mapper_(params, std::move(shared)) {
  SLAMTUNE_CHECK(log_ != nullptr);
  if (log_->scans.empty()) throw InputError(log_->path, 0, "the log has no laser scans");
  frame_ = OdometryFrameOf(*log_);
  lasers_ = std::make_shared<const LogLasers>(LasersOf(*log_, params, frame_));
  state_of_log_scan_.assign(log_->scans.size(), -1);
}

ProcessResult LogRunner::Step() {
  SLAMTUNE_CHECK(!Done());
  const auto start = std::chrono::steady_clock::now();
  const std::size_t index = next_++;
  ProcessResult result;
  const io::LaserScanRecord& record = log_->scans[index];
  const NodeVerdict verdict = node_filter_.Offer(mapper_.params(), record.robot_pose, io::StampNs(record));
  if (verdict != NodeVerdict::kPass) {
    ++refused_by_node_[static_cast<int>(verdict)];
    result.outcome = ProcessResult::Outcome::kRefusedByNode;
  } else {
    // The record's readings are shared with the log (aliasing pointer keeps the log alive).
    std::shared_ptr<const std::vector<double>> ranges(log_, &record.ranges);
    const int laser = lasers_->LaserOf(index);
    std::shared_ptr<const LaserGeometry> geometry = lasers_->geometries[laser];
    if (static_cast<int>(record.ranges.size()) != geometry->num_readings) {
      // Another count than its laser's (one laser only): Karto refuses it (§2.1).
      geometry = std::make_shared<const LaserGeometry>(GeometryForRecord(record, mapper_.params(), frame_.offset));
    }
    LaserScan scan(geometry, ranges, OdometricPose(record, frame_), record.ipc_time);
    scan.log_index = static_cast<int>(index);
    scan.laser = laser;
    result = mapper_.Process(std::move(scan));
    state_of_log_scan_[index] = result.state_id;
    if (result.sequential_response >= 0.0) {
      sequential_matches_.push_back(
          StepOf(result, static_cast<int>(index), record.ipc_time - log_->scans.front().ipc_time, mapper_.params()));
    }
  }
  wall_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void LogRunner::RunToEnd(const std::function<void(std::size_t, std::size_t)>& progress) {
  while (!Done()) {
    Step();
    if (progress) progress(next_, size());
  }
}

RunSummary LogRunner::Summary() const {
  RunSummary s;
  const MapperCounters& c = mapper_.counters();
  s.scans_read = static_cast<int>(log_->scans.size());
  s.scans_offered = c.scans_offered;
  s.scans_refused_by_node = refused_by_node_;
  s.nodes = c.scans_processed;
  s.scans_not_moved = c.scans_not_moved;
  s.scans_wrong_reading_count = c.scans_wrong_reading_count;
  for (std::size_t l = 0; l < lasers_->geometries.size(); ++l) {
    s.nodes_per_laser.push_back(static_cast<int>(mapper_.scans_by_laser().scans_of(static_cast<int>(l)).size()));
  }
  s.edges = c.edges_added;
  s.duplicate_edges = c.duplicate_edges;
  s.near_chain_matches = c.near_chain_matches;
  s.near_chain_matches_skipped = c.near_chain_matches_skipped;
  s.loop_attempts = c.loop_attempts;
  for (const LoopAttempt& a : mapper_.loop_attempts()) {
    if (!a.accepted) continue;
    s.loop_closures.push_back({a.log_index, a.scan, a.chain_first, a.chain_last, a.linked_to, a.coarse_response,
                               a.fine_response, a.coarse_covariance(0, 0), a.coarse_covariance(0, 1),
                               a.coarse_covariance(1, 1)});
  }
  s.solver_runs = static_cast<int>(mapper_.solver_runs().size());
  for (const SolveSummary& run : mapper_.solver_runs()) s.solver_wall_s += run.wall_s;
  s.wall_s = wall_s_;
  s.log_duration_s = log_->scans.back().ipc_time - log_->scans.front().ipc_time;
  s.laser_max_range = lasers_->geometries.front()->max_range;
  s.range_threshold = lasers_->geometries.front()->range_threshold;
  return s;
}

io::KartoLaserRule LaserRuleOf(NodeMode mode) {
  return mode == NodeMode::kSlamKarto ? io::KartoLaserRule::kSlamKarto : io::KartoLaserRule::kSlamToolbox;
}

io::ScanLosses RunLosses(const io::LaserLog& log, const RunSummary& summary, NodeMode mode) {
  io::ScanLosses losses = io::ReadingLosses(log, LaserRuleOf(mode));
  io::ScanLoss& readings = losses.Get(io::ScanLossKind::kWrongReadingCount);
  readings.count = static_cast<std::size_t>(summary.scans_wrong_reading_count);  // as the run refused them
  io::ScanLoss& node = losses.Get(io::ScanLossKind::kFilteredByNode);
  node.count = static_cast<std::size_t>(summary.scans_refused_by_node_total());
  node.why = fmt::format("scans the node does not hand to Karto (node mode {})", NameOf(mode));
  for (int v = 1; v < kNumNodeVerdicts; ++v) {
    node.by[NameOf(static_cast<NodeVerdict>(v))] = static_cast<std::size_t>(summary.scans_refused_by_node[v]);
  }
  io::ScanLoss& moved = losses.Get(io::ScanLossKind::kNotMoved);
  moved.count = static_cast<std::size_t>(summary.scans_not_moved);
  moved.why =
      "scans Karto skips: the robot moved less than minimum_travel_distance and minimum_travel_heading "
      "since the last scan it mapped";
  return losses;
}

Pose2 LogRunner::OdometricSensorPose(const io::LaserScanRecord& record) const {
  return frame_.robot_poses ? Compose(record.robot_pose, frame_.offset) : record.laser_pose;
}

std::vector<io::TimedPose> LogRunner::Trajectory() const {
  std::vector<io::TimedPose> out;
  out.reserve(log_->scans.size());
  const std::vector<LaserScan>& scans = mapper_.scans();
  int previous = -1;  // state id of the preceding processed scan
  for (std::size_t i = 0; i < log_->scans.size(); ++i) {
    const io::LaserScanRecord& record = log_->scans[i];
    const int id = state_of_log_scan_[i];
    Pose2 pose;
    if (id >= 0) {
      pose = scans[id].SensorPose();
      previous = id;
    } else if (previous >= 0) {
      const LaserScan& p = scans[previous];
      pose = Compose(p.SensorPose(), Between(p.OdometricSensorPose(), OdometricSensorPose(record)));
    } else {
      pose = OdometricSensorPose(record);
    }
    out.push_back({record.ipc_time, pose});
  }
  return out;
}

RunResult RunLog(std::shared_ptr<const io::LaserLog> log, const MapperParams& params,
                 const std::function<void(std::size_t, std::size_t)>& progress) {
  LogRunner runner(std::move(log), params);
  runner.RunToEnd(progress);
  return {runner.Summary(), runner.Trajectory()};
}

}  // namespace slamtune::slam
