// Runs a recorded laser log (io::LaserLog) through the Karto mapper the way a slam_karto user
// replaying it would (docs/engine.md §2.3, §1.4 [DECIDE]): every scan in file order, the
// odometric poses and mounting offset of OdometryFrameOf (for CARMEN FLASER logs: the laser pose
// with a zero offset), readings unchanged,
// maxRange = min(laser_max_range_cap, the scan's no-return value), rangeThreshold by the rule
// of §9.2, time = ipc timestamp; the node's own choice of scans first (node_scan_filter.h: the
// node mode, throttle_scans, the synchronous node's filter). One Karto laser, made from the
// first scan, as both nodes make it; with --beams per-geometry (log.beams.policy) one laser per
// beam geometry instead (LasersOf, §3.5).
//
// LogRunner is a value with a step API: Step() processes one log scan, so the state after log
// scan k can be copied (with SetParams() on the copy) and both copies continued; results do not
// depend on whether a run was forked. RunLog() is the whole run in one call.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/scan_losses.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/slam/front_end_evidence.h"
#include "slamtune/slam/mapper.h"
#include "slamtune/slam/node_scan_filter.h"

namespace slamtune::slam {

// A loop closure as reported in loop_closures.csv and run.json.
struct LoopClosureRecord {
  int log_index = -1;    // log scan index of the current scan
  int node = -1;         // its state id
  int chain_first = -1;  // candidate chain, state ids
  int chain_last = -1;
  int linked_to = -1;  // chain member the loop edge starts from, -1: no edge added (§6.1)
  double coarse_response = 0.0;
  double fine_response = 0.0;
  double coarse_var_xx = 0.0, coarse_var_xy = 0.0, coarse_var_yy = 0.0;  // m^2
};

struct RunSummary {
  int scans_read = 0;     // laser scans in the log
  int scans_offered = 0;  // passed to Process (after the node's own filter)
  // Scans the node itself did not hand to Karto, by verdict (node_scan_filter.h; kPass unused).
  std::array<int, kNumNodeVerdicts> scans_refused_by_node{};
  int scans_refused_by_node_total() const;
  int nodes = 0;  // processed scans
  int scans_not_moved = 0;
  int scans_wrong_reading_count = 0;
  std::vector<int> nodes_per_laser;                  // processed scans of each laser (LogLasers order)
  std::array<int, kNumEdgeKinds> edges{};            // by EdgeKind
  std::array<int, kNumEdgeKinds> duplicate_edges{};  // dropped LinkScans calls
  int near_chain_matches = 0;                        // near chains tested (size >= g)
  int near_chain_matches_skipped = 0;                // of those, proven unable to link without matching
  int loop_attempts = 0;                             // candidate chains matched by the loop matcher
  std::vector<LoopClosureRecord> loop_closures;
  int solver_runs = 0;
  double solver_wall_s = 0.0;    // time spent in back-end solves
  double wall_s = 0.0;           // time spent in Step()
  double log_duration_s = 0.0;   // last - first ipc timestamp of the log's scans
  double laser_max_range = 0.0;  // maxRange used (m): laser 0's, made from the log's first scan
  double range_threshold = 0.0;  // rangeThreshold used (m): laser 0's
  int total_edges() const;
};

// How a log's scans are given to the mapper (docs/engine.md §1.4). When every scan has the
// same laser mounting offset (within kSameOffsetTolerance), as a robot's recording does, the
// mapper gets the robot's odometric poses and the offset as the laser's offset pose, as a ROS
// node gives Karto the base's odometry and the range finder's offset; sensor poses are then
// robot (+) offset, as in slam_karto (and the graph's frame follows robot_pose_graph). A log
// whose per-scan "offset" varies (laser poses from another source than the robot's) is given
// as laser poses with a zero offset. A log whose offset is zero is the same either way.
inline constexpr double kSameOffsetTolerance = 1e-9;  // m and rad
struct OdometryFrame {
  bool robot_poses = false;  // scans' robot_pose as odometry, `offset` as the laser's offset
  Pose2 offset;
};
OdometryFrame OdometryFrameOf(const io::LaserLog& log);
// A scan's odometric pose for the mapper in that frame.
inline const Pose2& OdometricPose(const io::LaserScanRecord& record, const OdometryFrame& frame) {
  return frame.robot_poses ? record.robot_pose : record.laser_pose;
}

// The Karto lasers a log is run with (docs/engine.md §3.5). One, made from the first scan,
// unless log.beams.policy is "per-geometry": then one per beam geometry (io::GeometryOf, the same
// within io::kSameAngleTolerance), made from the first scan that has it, numbered in order of
// first appearance in the log. Each scan is read with its laser's exact angles.
struct LogLasers {
  std::vector<std::shared_ptr<const LaserGeometry>> geometries;  // by laser
  // "laser_0", "laser_1", ...: the names a user would give the lasers' frames so that Karto,
  // which takes its lasers in name order, takes them in this order (zero-padded past 10).
  std::vector<std::string> names;
  std::vector<int> laser_of_scan;  // by log scan; empty: every scan is laser 0's
  int LaserOf(std::size_t log_index) const { return laser_of_scan.empty() ? 0 : laser_of_scan[log_index]; }
};
LogLasers LasersOf(const io::LaserLog& log, const MapperParams& params, const OdometryFrame& frame);

class LogRunner {
 public:
  // Validates `params`. The log is shared (read-only) by all copies of the runner. `shared`
  // lets runs of this same log share scan matches, back-end solves and barycentres
  // (sharing/shared_work.h); results are identical with or without it.
  LogRunner(std::shared_ptr<const io::LaserLog> log, const MapperParams& params, SharedWork shared = {});

  bool Done() const { return next_ >= log_->scans.size(); }
  std::size_t next_index() const { return next_; }
  std::size_t size() const { return log_->scans.size(); }
  // Processes log scan next_index() (or skips it when the node would not hand it to Karto).
  // Returns what Process did; a scan the node refused reports Outcome::kRefusedByNode.
  ProcessResult Step();
  // Steps to the end; `progress(done, total)` is called after every step when set.
  void RunToEnd(const std::function<void(std::size_t, std::size_t)>& progress = {});

  // Changes parameters for the scans still to come (see Mapper::SetParams). The lasers stay
  // the ones built at construction.
  void SetParams(const MapperParams& params) { mapper_.SetParams(params); }
  const Mapper& mapper() const { return mapper_; }
  // Every match and solve is also written to `trace` (run_trace.h); null: none.
  void set_trace(std::shared_ptr<RunTrace> trace) { mapper_.set_trace(std::move(trace)); }
  // See Mapper::set_skip_unlinkable_near_chains (same results either way).
  void set_skip_unlinkable_near_chains(bool on) { mapper_.set_skip_unlinkable_near_chains(on); }
  const io::LaserLog& log() const { return *log_; }
  const LogLasers& lasers() const { return *lasers_; }

  RunSummary Summary() const;
  // Every sequential match so far, in log order (front_end_evidence.h).
  const std::vector<SequentialMatchStep>& sequential_matches() const { return sequential_matches_; }
  // One pose per log scan (time = ipc timestamp): a processed scan's current sensor pose; any
  // other scan the preceding processed scan's pose composed with the odometry increment since
  // it (odometry itself before the first processed scan). Scans not yet stepped are included
  // the same way, so call it after RunToEnd() for the final trajectory.
  std::vector<io::TimedPose> Trajectory() const;

 private:
  // The sensor pose the odometry gives for a log scan (as LaserScan::OdometricSensorPose).
  Pose2 OdometricSensorPose(const io::LaserScanRecord& record) const;

  std::shared_ptr<const io::LaserLog> log_;
  OdometryFrame frame_;
  std::shared_ptr<const LogLasers> lasers_;  // shared by copies
  Mapper mapper_;
  std::size_t next_ = 0;
  std::vector<int> state_of_log_scan_;  // state id per log scan, -1 if not processed
  std::vector<SequentialMatchStep> sequential_matches_;
  NodeScanFilter node_filter_;
  std::array<int, kNumNodeVerdicts> refused_by_node_{};
  double wall_s_ = 0.0;
};

// Laser geometry of a log scan record for these parameters (§2.3, §9.2), with `offset` as the
// laser's offset pose.
LaserGeometry GeometryForRecord(const io::LaserScanRecord& record, const MapperParams& params,
                                const Pose2& offset = {});

// Every scan of the log the run did not map, by why (io/scan_losses.h): what the recording
// decides for the run's node (`mode`), the reading count as the engine refused it, the node's
// filter by verdict and Karto's travel gate.
io::ScanLosses RunLosses(const io::LaserLog& log, const RunSummary& summary, NodeMode mode);
// The Karto laser rule of the node a mode runs (slam_karto's, or slam_toolbox's for its modes).
io::KartoLaserRule LaserRuleOf(NodeMode mode);

// The whole log in one call.
struct RunResult {
  RunSummary summary;
  std::vector<io::TimedPose> trajectory;
};
RunResult RunLog(std::shared_ptr<const io::LaserLog> log, const MapperParams& params,
                 const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace slamtune::slam
