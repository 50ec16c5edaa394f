// Karto's correlative scan matcher (docs/engine.md §4): a byte correlation grid with
// Gaussian smearing built from base scans seen from the scan's position (back-face filter),
// an exhaustive coarse search over (y, x, theta), an optional fine pass, and the response and
// covariance rules that gate loop closure.
//
// One ScanMatcher per role: the mapper keeps a *sequential* matcher (CorrelationSearchSpace*
// parameters) and a *loop* matcher (LoopSearchSpace* parameters). The matcher owns its grids
// and lookup tables and reuses them between calls; it is a value type (copying it copies the
// caches), so engine state can be copied and continued.
//
// Speed without changing a bit: the search works on integer byte sums (vectorised, far points
// clipped per row), unpenalised coarse passes skip candidates provably > 0.1 below the best
// (fast_matching/pruned_search.h), and the results equal those of ReferenceScanMatcher, a plain
// transcription of Karto's loops (scan_matcher_test.cc checks it on synthetic and intel data).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <span>

#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam {

// Parameters of one matcher. Internal units (variance penalties already squared, §9.1).
struct ScanMatcherOptions {
  double search_dimension = 0.3;               // m, side of the xy search window (CorrelationSearchSpaceDimension)
  double search_resolution = 0.01;             // m, grid cell size rho
  double smear_deviation = 0.03;               // m, sigma of the smearing kernel
  double range_threshold = 12.0;               // m, sets the grid margin (§4.1)
  double coarse_angle_offset = 0.349066;       // rad, +- range of the coarse angle search
  double coarse_angle_resolution = 0.0349066;  // rad, coarse angle step
  double fine_angle_step = 0.0034907;          // rad, FineSearchAngleOffset (a step, §4.2 item 6)
  double distance_variance_penalty = 0.09;     // m^2 (internal, = ROS value squared)
  double angle_variance_penalty = 0.121847;    // rad^2 (internal)
  double minimum_distance_penalty = 0.5;
  double minimum_angle_penalty = 0.9;
  bool use_response_expansion = false;
  int threads = 1;  // rows of an exhaustive coarse search spread over this many threads; results independent of it
  // Skip, in unpenalised coarse passes over small grids (the loop matcher), the blocks of
  // candidates provably more than 0.1 below the best response (fast_matching/pruned_search.h); results are
  // identical either way, only the time changes.
  bool branch_and_bound = true;

  // Throws InputError naming the field when D/rho is not an even integer, sigma is outside
  // [0.5 rho, 10 rho], or a value is non-positive (§4.1 [DECIDE]); also when a minimum
  // penalty is outside [0, 1], threads < 1, or the correlation grid would exceed 2^31 cells
  // (32-bit linear indices, §1.2).
  void Validate() const;
};

struct MatchResult {
  Pose2 mean;  // sensor pose of the best match
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  double response = 0.0;  // in [0, 1]
};

// Stands for a match that was not computed because its response provably cannot exceed the
// caller's threshold (fast_matching/response_bound.h): the response is -inf, below every threshold.
inline MatchResult ProvenBelowThreshold() {
  MatchResult r;
  r.response = -std::numeric_limits<double>::infinity();
  return r;
}
inline bool IsProvenBelowThreshold(const MatchResult& r) {
  return r.response == -std::numeric_limits<double>::infinity();
}

// MatchScan's doPenalize (§4.5): whether each candidate's response is scaled down by its
// distance and heading from the scan's pose.
enum class Penalize : bool { kNo, kYes };
// MatchScan's doRefine (§4.2 item 6): whether a fine pass around the coarse mean follows the
// coarse one.
enum class Refine : bool { kNo, kYes };

class ScanMatcher {
 public:
  explicit ScanMatcher(const ScanMatcherOptions& options);
  ScanMatcher(const ScanMatcher&);
  ScanMatcher& operator=(const ScanMatcher&);
  ScanMatcher(ScanMatcher&&) noexcept;
  ScanMatcher& operator=(ScanMatcher&&) noexcept;
  ~ScanMatcher();

  // MatchScan(scan, baseScans, doPenalize, doRefine) of §4.2: matches `scan` (at its current
  // sensor pose) against `base_scans` (in the given order: running buffer oldest -> newest,
  // chains in increasing state id). Returns the mean sensor pose, the covariance (positional
  // part from the coarse pass, angular from the fine pass when refining) and the response.
  MatchResult Match(const LaserScan& scan, std::span<const LaserScan* const> base_scans, Penalize penalize,
                    Refine refine);

  const ScanMatcherOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace slamtune::slam
