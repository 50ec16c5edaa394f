// A plain transcription of Karto's MatchScan / CorrelateScan (docs/engine.md §4.2-§4.6):
// responses accumulated per pose in double, every lookup entry bounds-checked, one pose at a
// time in the loop order y, x, heading, the whole grid cleared on every call, no threads.
//
// It exists to pin down the fast ScanMatcher: the tests require both to give bit-identical
// means, covariances and responses, and bench/bench_matcher.cc reports the speed-up over it.
// It shares the grid construction (CorrelationGrid), the lookup-table arithmetic
// (ScanLookupTable::Compute) and the covariance formulas (match_covariance.h) with the fast
// matcher; those have their own tests against docs/engine.md.
#pragma once

#include <span>
#include <vector>

#include "slamtune/slam/matching/correlation_grid.h"
#include "slamtune/slam/matching/match_covariance.h"
#include "slamtune/slam/matching/scan_lookup_table.h"
#include "slamtune/slam/matching/scan_matcher.h"

namespace slamtune::slam {

class ReferenceScanMatcher {
 public:
  // Options are validated as for ScanMatcher; `threads` is ignored.
  explicit ReferenceScanMatcher(const ScanMatcherOptions& options);

  MatchResult Match(const LaserScan& scan, std::span<const LaserScan* const> base_scans, Penalize penalize,
                    Refine refine);

 private:
  struct Candidate {
    double response;
    Pose2 pose;
  };
  // The coarse pass fills the probability grid and the positional covariance, the fine pass
  // gives the angular variance.
  enum class Pass { kCoarse, kFine };
  double CorrelateScan(const LaserScan& scan, const Pose2& center, double offset_xy, double step_xy,
                       double angle_offset, double angle_step, Penalize penalize, Pass pass, Pose2* mean,
                       Eigen::Matrix3d* cov);
  // Karto's GetResponse: sum of bytes over valid, in-range entries / (100 * all entries).
  double Response(int angle_index, std::int32_t cell_index) const;

  ScanMatcherOptions options_;
  CorrelationGrid grid_;
  SearchProbabilityGrid probabilities_;
  ScanLookupTable table_;
};

}  // namespace slamtune::slam
