#include "slamtune/slam/mapper.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/slam/backend/make_solver.h"
#include "slamtune/slam/loop_closure.h"
#include "slamtune/slam/near_chains.h"

namespace slamtune::slam {
namespace {

// ScanMatcherOptions has no operator==; the matcher is rebuilt when any field differs.
bool SameOptions(const ScanMatcherOptions& a, const ScanMatcherOptions& b) {
  return a.search_dimension == b.search_dimension && a.search_resolution == b.search_resolution &&
         a.smear_deviation == b.smear_deviation && a.range_threshold == b.range_threshold &&
         a.coarse_angle_offset == b.coarse_angle_offset && a.coarse_angle_resolution == b.coarse_angle_resolution &&
         a.fine_angle_step == b.fine_angle_step && a.distance_variance_penalty == b.distance_variance_penalty &&
         a.angle_variance_penalty == b.angle_variance_penalty &&
         a.minimum_distance_penalty == b.minimum_distance_penalty &&
         a.minimum_angle_penalty == b.minimum_angle_penalty && a.use_response_expansion == b.use_response_expansion &&
         a.threads == b.threads;
}

// The solve cache's stored barycentres (§2.2) depend on each node's scan: its readings (its log
// index: the cache is shared by runs of one log) and its laser geometry. Appends each distinct
// geometry's words once, then one word per scan: the geometry's place in that list and the log index.
void AppendScansKey(std::span<const LaserScan> scans, std::vector<std::uint64_t>* key) {
  std::vector<const LaserGeometry*> geometries;
  std::vector<std::uint64_t> words;
  words.reserve(scans.size());
  for (const LaserScan& s : scans) {
    auto it = std::find(geometries.begin(), geometries.end(), &s.geometry());
    if (it == geometries.end()) it = geometries.insert(it, &s.geometry());
    const auto place = static_cast<std::uint64_t>(it - geometries.begin());
    words.push_back(place << 32 | static_cast<std::uint32_t>(s.log_index));
  }
  key->push_back(geometries.size());
  for (const LaserGeometry* g : geometries) AppendGeometryKey(*g, key);
  key->insert(key->end(), words.begin(), words.end());
}

}  // namespace

Mapper::Mapper(const MapperParams& params, SharedWork shared) : params_(params), shared_(std::move(shared)) {
  params_.Validate();
  solver_ = MakeSolver(params_.solver, params_.Ceres());
}

void Mapper::SetParams(const MapperParams& params) {
  params.Validate();
  if (params.use_scan_matching != params_.use_scan_matching && !scans_.empty()) {
    throw InputError("use_scan_matching cannot change after the first processed scan");
  }
  auto solver = MakeSolver(params.solver, params.Ceres());
  const bool barycenter_changed = params.use_scan_barycenter != params_.use_scan_barycenter;
  params_ = params;
  solver_ = std::move(solver);
  if (geometry_ && params_.use_scan_matching) {
    const double rt = geometry_->range_threshold;
    if (!sequential_matcher_ || !SameOptions(sequential_matcher_->options(), params_.SequentialMatcherOptions(rt)) ||
        !SameOptions(loop_matcher_->options(), params_.LoopMatcherOptions(rt))) {
      BuildMatchers();
    }
  }
  if (barycenter_changed) {
    for (std::size_t k = 0; k < scans_.size(); ++k) {
      reference_poses_[k] = scans_[k].ReferencePose(params_.use_scan_barycenter);
    }
  }
}

void Mapper::BuildMatchers() {
  const double rt = geometry_->range_threshold;
  sequential_matcher_.emplace(params_.SequentialMatcherOptions(rt));
  near_chain_bound_.emplace(params_.SequentialMatcherOptions(rt));
  loop_matcher_.emplace(params_.LoopMatcherOptions(rt));
}

void Mapper::SetScanSensorPose(int id, const Pose2& sensor_pose) {
  scans_[id].SetSensorPose(sensor_pose);
  UpdateReferencePose(id);
}

void Mapper::UpdateReferencePose(int id) {
  if (params_.use_scan_barycenter && shared_.barycenter_cache) shared_.barycenter_cache->Provide(scans_[id]);
  reference_poses_[static_cast<std::size_t>(id)] = scans_[id].ReferencePose(params_.use_scan_barycenter);
}

const std::deque<int>& Mapper::running_buffer(int laser) const {
  static const std::deque<int> kNone;
  return laser >= 0 && laser < static_cast<int>(lasers_.size()) ? lasers_[laser].running_buffer : kNone;
}

std::vector<const LaserScan*> Mapper::ScanPointers(std::span<const int> ids) const {
  std::vector<const LaserScan*> out;
  out.reserve(ids.size());
  for (int id : ids) out.push_back(&scans_[id]);
  return out;
}

MatchResult Mapper::MatchWith(MatchRole role, const LaserScan& scan, const std::vector<const LaserScan*>& base,
                              Penalize penalize, Refine refine) {
  ScanMatcher& matcher = role == MatchRole::kLoop ? *loop_matcher_ : *sequential_matcher_;
  if (shared_.match_cache) return shared_.match_cache->Match(role, matcher, scan, base, penalize, refine);
  return matcher.Match(scan, base, penalize, refine);
}

// §3.2, steps 1-10 in order, with the scan's own laser's last scan and running buffer (§3.5).
ProcessResult Mapper::Process(LaserScan scan) {
  ProcessResult result;
  ++counters_.scans_offered;
  SLAMTUNE_CHECK(scan.laser >= 0 && scan.laser < ScansByLaser::kMaxLasers);
  const int laser = scan.laser;
  if (laser >= static_cast<int>(lasers_.size())) lasers_.resize(static_cast<std::size_t>(laser) + 1);
  // 1. Reading count must match the laser's, as its first scan fixed it (§2.1).
  const LaserGeometry* expected = lasers_[laser].geometry.get();
  if (expected != nullptr && scan.geometry().num_readings != expected->num_readings) {
    ++counters_.scans_wrong_reading_count;
    result.outcome = ProcessResult::Outcome::kWrongReadingCount;
    return result;
  }
  // 2. First call: the matchers (their grids depend on the range threshold).
  if (!geometry_) {
    geometry_ = scan.geometry_ptr();
    if (params_.use_scan_matching) BuildMatchers();
  }
  if (expected == nullptr) lasers_[laser].geometry = scan.geometry_ptr();
  // 3-4. Initial guess from the odometry increment since the laser's last processed scan.
  const std::span<const int> own = scans_by_laser_.scans_of(laser);
  const LaserScan* last = own.empty() ? nullptr : &scans_[own.back()];
  if (last != nullptr) {
    scan.SetCorrectedPose(InitialGuess(last->odometric_pose(), last->corrected_pose(), scan.odometric_pose()));
  }
  // 5. HasMovedEnough.
  const MovementOptions movement{params_.minimum_time_interval, params_.minimum_travel_distance,
                                 params_.minimum_travel_heading};
  result.move = HasMovedEnough(scan, last, movement);
  if (result.move == MoveDecision::kNotMoved) {
    ++counters_.scans_not_moved;
    result.outcome = ProcessResult::Outcome::kNotMoved;
    return result;
  }
  // 6-7. Sequential match against the laser's running buffer, penalties and refinement on.
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  if (params_.use_scan_matching && last != nullptr) {
    const std::deque<int>& running = lasers_[laser].running_buffer;
    const std::vector<int> buffer_ids(running.begin(), running.end());
    const std::vector<const LaserScan*> buffer = ScanPointers(buffer_ids);
    result.sequential_guess = scan.SensorPose();
    const MatchResult match = MatchWith(MatchRole::kSequential, scan, buffer, Penalize::kYes, Refine::kYes);
    TraceMatch("sequential", static_cast<int>(scans_.size()), scan.log_index, buffer_ids, result.sequential_guess,
               match, "used");
    scan.SetSensorPose(match.mean);
    covariance = match.covariance;
    result.sequential_response = match.response;
    result.sequential_mean = match.mean;
    result.sequential_covariance = match.covariance;
  }
  // 8. Register the scan.
  const int id = static_cast<int>(scans_.size());
  scan.state_id = id;
  scans_.push_back(std::move(scan));
  scans_by_laser_.Add(laser);
  reference_poses_.emplace_back();
  UpdateReferencePose(id);
  ++counters_.scans_processed;
  result.state_id = id;
  // 9. Graph, edges, running buffer, loop closure.
  if (params_.use_scan_matching) {
    graph_.AddVertex(scans_[id].corrected_pose());  // 9a: node = pose after the sequential match
    AddEdges(id, covariance, &result);              // 9b
    std::deque<int>& running = lasers_[laser].running_buffer;
    running.push_back(id);  // 9c, §3.3
    TrimRunningBuffer(
        running, [this](int k) { return scans_[k].SensorPose(); }, params_.scan_buffer_size,
        params_.scan_buffer_maximum_scan_distance);
    if (params_.do_loop_closing) {
      // 9d, on every laser's scans in laser order (§3.5)
      for (int l = 0; l < scans_by_laser_.num_lasers(); ++l) result.loops_closed += TryCloseLoop(id, l, &result);
    }
  }
  // 10. The scan is now its laser's last processed scan (the last of scans_by_laser_.scans_of(laser)).
  return result;
}

bool Mapper::Link(int from, int to, const Pose2& mean, const Eigen::Matrix3d& covariance, EdgeKind kind,
                  ProcessResult* result) {
  // slam_toolbox labels edges with robot poses (the mean converted to the robot frame, the
  // sensor-frame covariance kept); slam_karto with sensor poses.
  const bool robot = params_.robot_pose_graph;
  const Pose2 from_pose = robot ? scans_[from].corrected_pose() : scans_[from].SensorPose();
  const Pose2 to_pose = robot ? RobotPoseFromSensor(mean, scans_[to].geometry().offset) : mean;
  const bool added = graph_.LinkScans(from, to, from_pose, to_pose, covariance, kind);
  const auto k = static_cast<std::size_t>(kind);
  if (added) {
    ++counters_.edges_added[k];
    ++result->edges_added[k];
  } else {
    ++counters_.duplicate_edges[k];
  }
  return added;
}

// §5.2 LinkChainToScan: returns the closest member linked from, or -1 when it is beyond
// LinkScanMaximumDistance (nothing added). A duplicate still returns the member.
int Mapper::LinkChainToScan(const std::vector<int>& chain, int scan, const Pose2& mean,
                            const Eigen::Matrix3d& covariance, EdgeKind kind, ProcessResult* result) {
  const int closest = ClosestInChain(chain, reference_poses_, scan);
  const double l = params_.link_scan_maximum_distance;
  if (SquaredDistance(reference_poses_[closest], reference_poses_[scan]) >= l * l + kKartoTolerance) return -1;
  Link(closest, scan, mean, covariance, kind, result);
  return closest;
}

// §5.3 with the scan's own laser's previous scan and running buffer; the first scan of a laser
// is linked to the other lasers instead (§3.5).
void Mapper::AddEdges(int scan, const Eigen::Matrix3d& covariance, ProcessResult* result) {
  std::vector<Pose2> means;
  std::vector<Eigen::Matrix3d> covariances;
  const int laser = scans_by_laser_.laser_of(scan);
  const int position = scans_by_laser_.position(scan);
  if (position > 0) {
    const Pose2 pose = scans_[scan].SensorPose();
    const int previous = scans_by_laser_.scans_of(laser)[position - 1];
    Link(previous, scan, pose, covariance, EdgeKind::kSequential, result);  // 1. previous scan
    means.push_back(pose);                                                  // 2. running buffer
    covariances.push_back(covariance);
    const std::deque<int>& running = lasers_[laser].running_buffer;
    if (!running.empty()) {
      LinkChainToScan(std::vector<int>(running.begin(), running.end()), scan, pose, covariance,
                      EdgeKind::kRunningBuffer, result);
    }
  } else {
    LinkToOtherLasers(scan, &means, &covariances, result);
  }
  LinkNearChains(scan, &means, &covariances, result);                             // 3.
  if (!means.empty()) SetScanSensorPose(scan, WeightedMean(means, covariances));  // 4.
}

// §3.5: matched from its pose now (the odometry's) with the sequential matcher, penalties and
// refinement on, against all scans of each other laser in laser order; the edge from that
// laser's first scan is added whatever the response, the mean joins the weighted mean only
// when the response exceeds link_match_minimum_response_fine.
void Mapper::LinkToOtherLasers(int scan, std::vector<Pose2>* means, std::vector<Eigen::Matrix3d>* covariances,
                               ProcessResult* result) {
  const int own = scans_by_laser_.laser_of(scan);
  for (int laser = 0; laser < scans_by_laser_.num_lasers(); ++laser) {
    const std::span<const int> other = scans_by_laser_.scans_of(laser);
    if (laser == own || other.empty()) continue;
    const Pose2 pose_in = scans_[scan].SensorPose();
    const MatchResult m =
        MatchWith(MatchRole::kSequential, scans_[scan], ScanPointers(other), Penalize::kYes, Refine::kYes);
    Link(other.front(), scan, m.mean, m.covariance, EdgeKind::kLaserLink, result);
    const bool used = m.response > params_.link_match_minimum_response_fine;
    if (used) {
      means->push_back(m.mean);
      covariances->push_back(m.covariance);
    }
    TraceMatch("laser_link", scan, scans_[scan].log_index, other, pose_in, m, used ? "used" : "not_used");
  }
}

MatchResult Mapper::MatchNearChain(const LaserScan& scan, const std::vector<const LaserScan*>& base, double threshold) {
  if (!skip_unlinkable_near_chains_) return MatchWith(MatchRole::kSequential, scan, base, Penalize::kNo, Refine::kYes);
  // A match proven unable to exceed the threshold would be computed only to be discarded
  // (fast_matching/response_bound.h). With a match cache the proof is stored like a result, so a run
  // repeating this call pays for neither.
  const auto may_exceed = [&] { return near_chain_bound_->MayExceed(scan, base, threshold); };
  if (shared_.match_cache) {
    return shared_.match_cache->MatchAbove(*sequential_matcher_, scan, base, Penalize::kNo, Refine::kYes, threshold,
                                           may_exceed);
  }
  return may_exceed() ? sequential_matcher_->Match(scan, base, Penalize::kNo, Refine::kYes) : ProvenBelowThreshold();
}

void Mapper::LinkNearChains(int scan, std::vector<Pose2>* means, std::vector<Eigen::Matrix3d>* covariances,
                            ProcessResult* result) {
  const auto chains =
      FindNearChains(graph_, reference_poses_, scans_by_laser_, scan, params_.link_scan_maximum_distance);
  const double threshold = params_.link_match_minimum_response_fine - kKartoTolerance;  // the edge needs more
  for (const std::vector<int>& chain : chains) {
    if (static_cast<int>(chain.size()) < params_.loop_match_minimum_chain_size) continue;  // g gates here too
    ++counters_.near_chain_matches;
    const Pose2 pose_in = scans_[scan].SensorPose();
    const MatchResult m = MatchNearChain(scans_[scan], ScanPointers(chain), threshold);
    const int log_index = scans_[scan].log_index;
    if (IsProvenBelowThreshold(m)) {
      ++counters_.near_chain_matches_skipped;
      TraceMatch("near_chain", scan, log_index, chain, pose_in, m, "proven_below");
      continue;
    }
    if (m.response > threshold) {
      means->push_back(m.mean);
      covariances->push_back(m.covariance);
      const int linked = LinkChainToScan(chain, scan, m.mean, m.covariance, EdgeKind::kNearChain, result);
      TraceMatch("near_chain", scan, log_index, chain, pose_in, m, linked < 0 ? "too_far" : "linked");
    } else {
      TraceMatch("near_chain", scan, log_index, chain, pose_in, m, "below");
    }
  }
}

// §6.1 along the scans of `laser` (§3.5). The cursor is shared by all candidate searches of this call.
int Mapper::TryCloseLoop(int scan, int laser, ProcessResult* result) {
  const LoopSearchOptions search{params_.loop_search_maximum_distance, params_.loop_match_minimum_chain_size};
  const double q2 = params_.LoopMatchMaximumVarianceCoarseInternal();
  int closed = 0;
  int cursor = 0;
  const std::span<const int> walk = scans_by_laser_.scans_of(laser);
  std::vector<int> chain = FindPossibleLoopClosure(graph_, reference_poses_, walk, scan, search, &cursor);
  while (!chain.empty()) {
    LoopAttempt attempt;
    attempt.log_index = scans_[scan].log_index;
    attempt.scan = scan;
    attempt.chain_first = chain.front();
    attempt.chain_last = chain.back();
    const std::vector<const LaserScan*> base = ScanPointers(chain);
    const Pose2 pose_in = scans_[scan].SensorPose();
    const MatchResult coarse = MatchWith(MatchRole::kLoop, scans_[scan], base, Penalize::kNo, Refine::kNo);
    attempt.coarse_response = coarse.response;
    attempt.coarse_covariance = coarse.covariance;
    // §6.3: strict on all three.
    attempt.coarse_passed = coarse.response > params_.loop_match_minimum_response_coarse &&
                            coarse.covariance(0, 0) < q2 && coarse.covariance(1, 1) < q2;
    TraceMatch("loop_coarse", scan, attempt.log_index, chain, pose_in, coarse,
               attempt.coarse_passed ? "passed" : "rejected");
    if (attempt.coarse_passed) {
      LaserScan tmp = scans_[scan];
      tmp.SetSensorPose(coarse.mean);
      const MatchResult fine = MatchWith(MatchRole::kSequential, tmp, base, Penalize::kNo, Refine::kYes);
      attempt.fine_response = fine.response;
      attempt.accepted = fine.response >= params_.loop_match_minimum_response_fine;  // §6.4
      TraceMatch("loop_fine", scan, attempt.log_index, chain, coarse.mean, fine,
                 attempt.accepted ? "accepted" : "rejected");
      if (attempt.accepted) {
        SetScanSensorPose(scan, fine.mean);
        attempt.linked_to = LinkChainToScan(chain, scan, fine.mean, fine.covariance, EdgeKind::kLoop, result);
        attempt.solver_run = CorrectPoses();
        ++closed;
        ++counters_.loops_closed;
      }
    }
    ++counters_.loop_attempts;
    loop_attempts_.push_back(attempt);
    chain = FindPossibleLoopClosure(graph_, reference_poses_, walk, scan, search, &cursor);
  }
  return closed;
}

// §7.1 CorrectPoses: one full solve, then every node's value is written back as the scan's
// sensor pose. Returns the index of the run in solver_runs_.
int Mapper::CorrectPoses() {
  std::vector<Pose2>& nodes = graph_.mutable_node_values();
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::uint64_t> key;
  std::optional<SolveCache::Solved> stored;
  if (shared_.solve_cache) {
    key = SolveCache::KeyOf(solver_->Identity(), nodes, graph_.edges());
    key.push_back(params_.robot_pose_graph ? 1 : 0);  // how the values are written back
    // The stored barycentres also depend on each node's scan and laser (range threshold, ...).
    AppendScansKey(scans_, &key);
    stored = shared_.solve_cache->Find(key);
  }
  if (stored) {
    // Another run made this very solve: its node values, and the barycentres it computed.
    SLAMTUNE_CHECK(stored->nodes.size() == nodes.size());
    nodes = stored->nodes;
    solver_runs_.push_back(stored->summary);
  } else {
    solver_runs_.push_back(solver_->Solve(nodes, graph_.edges()));
  }
  SolveSummary& summary = solver_runs_.back();
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (summary.usable) {
    const bool known = stored && stored->barycenters.size() == nodes.size();
    // Node values are sensor poses (slam_karto) or robot poses (slam_toolbox's robot_pose_graph).
    const bool robot = params_.robot_pose_graph;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (known) {
        if (robot) {
          scans_[k].SetCorrectedPoseWithBarycenter(nodes[k], stored->barycenters[k]);
        } else {
          scans_[k].SetSensorPoseWithBarycenter(nodes[k], stored->barycenters[k]);
        }
        reference_poses_[k] = scans_[k].ReferencePose(params_.use_scan_barycenter);
      } else if (robot) {
        scans_[k].SetCorrectedPose(nodes[k]);
        UpdateReferencePose(static_cast<int>(k));
      } else {
        SetScanSensorPose(static_cast<int>(k), nodes[k]);
      }
    }
  }
  if (shared_.solve_cache && !stored) {
    SolveCache::Solved solved{summary, nodes, {}};
    if (summary.usable && params_.use_scan_barycenter) {
      solved.barycenters.reserve(nodes.size());
      for (const LaserScan& s : scans_) solved.barycenters.push_back(s.barycenter());
    }
    shared_.solve_cache->Store(std::move(key), std::move(solved));
  }
  const int index = static_cast<int>(solver_runs_.size()) - 1;
  if (trace_) {
    trace_->WriteSolve(index, static_cast<int>(nodes.size()), static_cast<int>(graph_.edges().size()), summary);
  }
  return index;
}

void Mapper::TraceMatch(const char* kind, int scan, int log_index, std::span<const int> base, const Pose2& pose_in,
                        const MatchResult& match, const char* decision) {
  if (!trace_) return;
  TracedMatch t;
  t.kind = kind;
  t.log_index = log_index;
  t.scan = scan;
  if (!base.empty()) {
    t.base_first = base.front();
    t.base_last = base.back();
  }
  t.base_size = static_cast<int>(base.size());
  t.pose_in = pose_in;
  t.response = match.response;
  t.mean = match.mean;
  t.covariance = match.covariance;
  t.decision = decision;
  trace_->WriteMatch(t);
}

}  // namespace slamtune::slam
