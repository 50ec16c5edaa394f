// A cheap, exact proof that a scan match cannot reach a response threshold, so that the
// mapper can skip near-chain matches whose result it would discard (docs/engine.md §5.3
// step 3: a near-chain match only adds an edge when its response exceeds
// link_match_minimum_response_fine - 1e-6; otherwise nothing of it is kept).
//
// Why: on intel 81 % of the 12 172 near-chain matches of a slam_karto run are rejected and
// 41 % have a response below 0.1: the chain saw little of what the scan sees. Each such match
// still builds a 6 MB correlation grid from the chain and scores every candidate pose.
//
// The bound. A beam adds at most 100 to a pose's sum (§4.5) and adds something only if the
// cell it reads is non-zero, i.e. within the kernel half-size h of a cell hit by a chain
// point (§4.3). Every pose the matcher scores (coarse lattice, its response expansions,
// the fine pass around the coarse mean, §4.2) lies within W = D/2 + rho of the scan's
// position and within a heading range [lo, hi] around its heading. Split the headings into
// buckets of half-width delta; a beam of range r at a heading in bucket k lands within
// W + r delta (a chord is shorter than its arc) of its end point q_k at the bucket's centre.
// With rounding (the candidate cell and the table offset are rounded separately, §4.4), a
// beam can score in bucket k only if some chain point lies within
// H = W + r delta + (h + 2.5) rho of q_k (Chebyshev distance). So
//   best response <= max_k (beams that can score in bucket k) / (all beams),
// counted on a coarse bitmap of the chain's points (a superset of the points the grid
// holds: the back-face filter only removes points). Beams whose reads may leave the stored
// grid (Karto's linear indices wrap rows, §1.2) are counted as scoring; beams whose reads
// all fall outside the linear range are not read at all (§4.5) and count zero.
//
// The bound is exact in the sense that matters: MayExceed(...) == false implies the match's
// response is <= threshold. It says nothing about the pose or covariance, so it is only
// used where a rejected match leaves no trace.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "slamtune/slam/laser_scan.h"
#include "slamtune/slam/matching/correlation_grid.h"
#include "slamtune/slam/matching/scan_matcher.h"

namespace slamtune::slam {

class ResponseBound {
 public:
  explicit ResponseBound(const ScanMatcherOptions& options);

  // False only if no pose Match(scan, base_scans, penalize, refine) scores can have a response
  // above `threshold` (penalties only lower responses, so either flag is covered). True when
  // some bucket's count reaches it, or when the heading range is too wide to bound (>= pi).
  bool MayExceed(const LaserScan& scan, std::span<const LaserScan* const> base_scans, double threshold);

  // The bound itself, as a sum: 100 x the largest bucket count (for tests; no early stop).
  std::int64_t MaxSumBound(const LaserScan& scan, std::span<const LaserScan* const> base_scans);

 private:
  // Places the grid as the matcher would for `scan` and marks the chain's points.
  void MarkChain(const LaserScan& scan, std::span<const LaserScan* const> base_scans);
  // Whether the bitmap holds a point in the metric box [lo, hi] (bitmap cells rounded outwards).
  bool AnyPointIn(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const;
  // What MaxCount must find: the largest bucket count (kExactMax), or only whether some bucket
  // reaches stop_at (kUntilStopAt: a count >= stop_at, returned as soon as one does, and a
  // smaller one if none does).
  enum class Count { kUntilStopAt, kExactMax };
  int MaxCount(const LaserScan& scan, int stop_at, Count goal);

  CorrelationGridGeometry geometry_;
  double resolution_;        // rho, as the grid reads it back (1 / scale)
  double window_;            // W: largest |offset| of a scored position from the scan's, per axis
  double heading_lo_ = 0.0;  // scored headings lie in [theta + lo, theta + hi]
  double heading_hi_ = 0.0;
  double bucket_half_ = 0.0;  // delta
  int num_buckets_ = 0;
  double slack_;  // (h + 2.5) rho
  double cell_;   // bitmap cell size s (metres)
  int words_per_row_ = 0;
  int side_ = 0;                     // bitmap columns = rows
  Eigen::Vector2d origin_{0, 0};     // ROI cell (0, 0) of the current match (metres)
  Eigen::Vector2d stored_lo_{0, 0};  // metric corner of the stored grid's cell (0, 0)
  // Each scan's points as cells of a world-aligned lattice of size s (so that they do not
  // depend on the match's origin), consecutive repeats dropped; kept while the scan's
  // readings and sensor pose are the same bits. The entry holds the readings, so their
  // address cannot be reused while it lives.
  struct ScanCells {
    std::shared_ptr<const std::vector<double>> ranges;
    Pose2 sensor_pose;
    std::vector<std::int32_t> cells;                            // x0, y0, x1, y1, ...
    std::int32_t min_x = 0, min_y = 0, max_x = -1, max_y = -1;  // their box (empty: max < min)
  };
  const ScanCells& CellsOf(const LaserScan& scan);
  std::unordered_map<const std::vector<double>*, ScanCells> scan_cells_;
  std::int32_t bitmap_x0_ = 0, bitmap_y0_ = 0;  // lattice cell of bitmap column / row 0
  std::vector<std::uint64_t> bits_;
  std::int32_t marked_x0_ = 0, marked_y0_ = 0, marked_x1_ = -1, marked_y1_ = -1;  // bitmap box of marked cells
  std::vector<int> bucket_order_;       // centre first, then alternating outwards
  std::vector<Eigen::Vector2d> local_;  // valid beams' end points in the sensor frame
  std::vector<double> reach_;           // W + r delta of each of them
};

}  // namespace slamtune::slam
