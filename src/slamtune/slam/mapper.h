// The Karto mapper (docs/engine.md §3, §5, §6, §7): Process() takes one scan through the
// front end in Karto's exact order (initial guess, HasMovedEnough, sequential match,
// vertex, AddEdges, running buffer, TryCloseLoop), links near chains, closes loops and runs
// one full back-end solve per accepted loop.
//
// Several lasers (§3.5): each scan names its laser (LaserScan::laser). As Karto's mapper does
// for several range finders, the initial guess, HasMovedEnough, the sequential match and the
// running buffer are per laser, the first scan of a laser is matched against and linked to the
// other lasers' scans, near chains and loop candidates run along one laser's scans, loops are
// sought on every laser in index order, and the graph and its solves span all lasers. The
// matchers are made once, with the first processed scan's range threshold. With one laser
// this is the single-laser mapper, decision for decision.
//
// State as a value: a Mapper holds everything the engine has (processed scans with their
// poses and points, the pose graph with the solver's node values, the running buffer, both
// scan matchers with their caches, counters and the loop-closure log). Copying a Mapper and
// continuing both copies with the same scans gives bit-identical results; SetParams() on a
// copy changes later decisions only (e.g. the loop-closure parameters r, g, p, q), so an
// optimiser can fork the state where decisions start to differ.
//
// Shared work (sharing/shared_work.h): with a MatchCache every matcher call (sequential, near
// chain, loop coarse, loop fine) goes through the cache, so runs of the same log that share it
// reuse each other's identical matches; with a SolveCache likewise every CorrectPoses solve, and
// with a BarycenterCache every barycentre a reference pose needs. Results are bit-identical with
// or without them.
#pragma once

#include <Eigen/Core>
#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "slamtune/slam/backend/pose_graph_solver.h"
#include "slamtune/slam/front_end.h"
#include "slamtune/slam/laser_scan.h"
#include "slamtune/slam/matching/fast_matching/response_bound.h"
#include "slamtune/slam/matching/scan_matcher.h"
#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/pose_graph.h"
#include "slamtune/slam/run_trace.h"
#include "slamtune/slam/scans_by_laser.h"
#include "slamtune/slam/sharing/shared_work.h"

namespace slamtune::slam {

// One loop candidate chain tried by TryCloseLoop (§6.1), accepted or not.
struct LoopAttempt {
  int log_index = -1;    // log index of the current scan
  int scan = -1;         // its state id
  int chain_first = -1;  // state ids of the candidate chain (consecutive)
  int chain_last = -1;
  double coarse_response = 0.0;                                 // s1, loop matcher, no penalty, no refinement
  Eigen::Matrix3d coarse_covariance = Eigen::Matrix3d::Zero();  // C1
  bool coarse_passed = false;                                   // s1 > p and both xy variances < q^2
  double fine_response = -1.0;  // s2 (sequential matcher on a copy at m1); -1 when not run
  bool accepted = false;        // s2 >= loop_match_minimum_response_fine
  int linked_to = -1;           // chain member the loop edge starts from; -1: no edge (§6.1 quirk)
  int solver_run = -1;          // index into Mapper::solver_runs() of the solve it triggered
};

// What Process() did with one scan.
struct ProcessResult {
  // kRefusedByNode: the ROS node kept it from Karto (LogRunner, node_scan_filter.h).
  enum class Outcome { kProcessed, kNotMoved, kWrongReadingCount, kRefusedByNode };
  Outcome outcome = Outcome::kProcessed;
  MoveDecision move = MoveDecision::kNotMoved;   // which test of HasMovedEnough accepted it
  int state_id = -1;                             // when processed
  std::array<int, kNumEdgeKinds> edges_added{};  // by EdgeKind
  int loops_closed = 0;
  double sequential_response = -1.0;  // response of the sequential match (-1 when none)
  // With a sequential match: the sensor pose it started from (the odometry's guess) and the
  // pose and covariance it found. What a front end that broke leaves behind
  // (front_end_evidence.h); Karto's decisions do not read them.
  Pose2 sequential_guess;
  Pose2 sequential_mean;
  Eigen::Matrix3d sequential_covariance = Eigen::Matrix3d::Zero();
};

struct MapperCounters {
  int scans_offered = 0;
  int scans_processed = 0;
  int scans_not_moved = 0;
  int scans_wrong_reading_count = 0;
  std::array<int, kNumEdgeKinds> edges_added{};
  std::array<int, kNumEdgeKinds> duplicate_edges{};  // LinkScans calls dropped as duplicates (§5.1)
  int near_chain_matches = 0;                        // near chains tested (size >= g)
  int near_chain_matches_skipped = 0;                // of those, proven unable to link (fast_matching/response_bound.h)
  int loop_attempts = 0;
  int loops_closed = 0;

  friend bool operator==(const MapperCounters&, const MapperCounters&) = default;
};

class Mapper {
 public:
  // Validates `params` (InputError) and picks the back-end. The caches of `shared` (each may be
  // null: that work is not shared) are shared by copies of the mapper.
  explicit Mapper(const MapperParams& params, SharedWork shared = {});

  // Mapper::Process of §3.2. `scan` carries its odometric pose (laser pose, zero offset for
  // CARMEN logs), time and laser index (0 <= laser < ScansByLaser::kMaxLasers); its log_index
  // is kept for reports. The first scan of each laser fixes that laser's reading count: its
  // later scans with another count are rejected (§2.1).
  ProcessResult Process(LaserScan scan);

  // Replaces the parameters for the scans still to come (validated first; on error nothing
  // changes). Matchers and back-end are rebuilt when their options change. use_scan_matching
  // cannot change once a scan has been processed.
  void SetParams(const MapperParams& params);
  const MapperParams& params() const { return params_; }
  // Every match and solve from now on is also written to `trace` (run_trace.h); null: none.
  void set_trace(std::shared_ptr<RunTrace> trace) { trace_ = std::move(trace); }

  // Skip the near-chain matches proven unable to reach link_match_minimum_response_fine
  // (fast_matching/response_bound.h). On by default; results are identical either way (tested), off is
  // for tests and timing.
  void set_skip_unlinkable_near_chains(bool on) { skip_unlinkable_near_chains_ = on; }

  // Processed scans, index = state id, with their current poses.
  const std::vector<LaserScan>& scans() const { return scans_; }
  // Which laser each processed scan belongs to, and each laser's scans in order (§3.5).
  const ScansByLaser& scans_by_laser() const { return scans_by_laser_; }
  // Reference poses (barycentres or sensor poses, §2.2) of the processed scans.
  const std::vector<Pose2>& reference_poses() const { return reference_poses_; }
  const PoseGraph& graph() const { return graph_; }
  // The running buffer of `laser` (§3.3); empty for a laser without scans.
  const std::deque<int>& running_buffer(int laser = 0) const;
  const std::vector<LoopAttempt>& loop_attempts() const { return loop_attempts_; }
  const std::vector<SolveSummary>& solver_runs() const { return solver_runs_; }
  const MapperCounters& counters() const { return counters_; }
  // State id of the last processed scan (of any laser), -1 before the first.
  int last_processed() const { return static_cast<int>(scans_.size()) - 1; }
  // Range threshold the matchers were made with (m): the first processed scan's laser's; 0
  // before the first scan.
  double range_threshold() const { return geometry_ ? geometry_->range_threshold : 0.0; }

 private:
  // What the mapper keeps per laser besides its scans (§3.1, §3.5): Karto's range finder and
  // the running buffer of its ScanManager.
  struct Laser {
    std::shared_ptr<const LaserGeometry> geometry;  // its first scan's: the reading count it accepts
    std::deque<int> running_buffer;
  };

  void BuildMatchers();
  void SetScanSensorPose(int id, const Pose2& sensor_pose);
  // reference_poses_[id] from the scan's current pose (its barycentre through the cache if any).
  void UpdateReferencePose(int id);
  std::vector<const LaserScan*> ScanPointers(std::span<const int> ids) const;
  // matcher.Match(...) of the given role, through the match cache when there is one.
  MatchResult MatchWith(MatchRole role, const LaserScan& scan, const std::vector<const LaserScan*>& base,
                        Penalize penalize, Refine refine);
  // LinkScans / LinkChainToScan of §5.1-§5.2, counting by kind; return whether an edge was added.
  bool Link(int from, int to, const Pose2& mean, const Eigen::Matrix3d& covariance, EdgeKind kind,
            ProcessResult* result);
  int LinkChainToScan(const std::vector<int>& chain, int scan, const Pose2& mean, const Eigen::Matrix3d& covariance,
                      EdgeKind kind, ProcessResult* result);
  void AddEdges(int scan, const Eigen::Matrix3d& covariance, ProcessResult* result);
  // §3.5: the first scan of a laser against every other laser with scans.
  void LinkToOtherLasers(int scan, std::vector<Pose2>* means, std::vector<Eigen::Matrix3d>* covariances,
                         ProcessResult* result);
  // A near-chain match whose result counts only above `threshold` (skipped when provably not).
  MatchResult MatchNearChain(const LaserScan& scan, const std::vector<const LaserScan*>& base, double threshold);
  void LinkNearChains(int scan, std::vector<Pose2>* means, std::vector<Eigen::Matrix3d>* covariances,
                      ProcessResult* result);
  // §6.1 on the scans of `laser`; returns the loops closed.
  int TryCloseLoop(int scan, int laser, ProcessResult* result);
  // Writes a match to the trace (when there is one); `base` are the state ids matched against.
  void TraceMatch(const char* kind, int scan, int log_index, std::span<const int> base, const Pose2& pose_in,
                  const MatchResult& match, const char* decision);
  int CorrectPoses();

  MapperParams params_;
  std::shared_ptr<const PoseGraphSolver> solver_;  // stateless, shared by copies
  // The first processed scan's laser: the matchers' range threshold (Karto's Initialize).
  std::shared_ptr<const LaserGeometry> geometry_;
  std::optional<ScanMatcher> sequential_matcher_;
  std::optional<ScanMatcher> loop_matcher_;
  std::optional<ResponseBound> near_chain_bound_;  // with the sequential matcher's options
  bool skip_unlinkable_near_chains_ = true;
  SharedWork shared_;                // caches may be null: no sharing; thread-safe, shared by copies
  std::shared_ptr<RunTrace> trace_;  // observer only; shared by copies
  std::vector<LaserScan> scans_;
  std::vector<Pose2> reference_poses_;
  ScansByLaser scans_by_laser_;
  std::vector<Laser> lasers_;  // by laser index
  PoseGraph graph_;
  std::vector<LoopAttempt> loop_attempts_;
  std::vector<SolveSummary> solver_runs_;
  MapperCounters counters_;
};

}  // namespace slamtune::slam
