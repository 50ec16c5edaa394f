#include "slamtune/slam/matching/fast_matching/response_bound.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {
namespace {

// Bitmap cells per correlation cell: coarse enough that a query box (about 1 m) spans a few
// words per row, fine enough to keep the bound tight.
constexpr double kCellsPerBitmapCell = 8.0;

// Headings of a lattice of K = Round(2 offset / step) + 1 values starting at -offset (§4.4),
// relative to its centre: [-offset, -offset + (K - 1) step].
void LatticeRange(double offset, double step, double* lo, double* hi) {
  const int k = KartoRoundToInt(offset * 2.0 / step) + 1;
  *lo = -offset;
  *hi = -offset + (k - 1) * step;
}

}  // namespace

ResponseBound::ResponseBound(const ScanMatcherOptions& options)
    : geometry_(CorrelationGridGeometry::Compute(options.search_dimension, options.search_resolution,
                                                 options.smear_deviation, options.range_threshold)),
      resolution_(1.0 / (1.0 / options.search_resolution)) {
  options.Validate();
  // Positions: the coarse lattice spans +-(n-1)/2 rho around the scan; the coarse mean stays
  // inside it and the fine pass adds +-rho (§4.2 items 4 and 6).
  window_ = 0.5 * (geometry_.search_side - 1) * resolution_ + resolution_;
  // Headings: the coarse lattice, widened up to three times by 20 degrees when response
  // expansion is on (§4.2 item 5); the coarse mean heading is a circular mean of lattice
  // headings, so it lies in that range while it is narrower than pi; the fine pass then
  // spans [mean - cr/2, mean - cr/2 + (Kf - 1) fs].
  const double cr = options.coarse_angle_resolution;
  double lo = 0.0, hi = 0.0;
  LatticeRange(options.coarse_angle_offset, cr, &lo, &hi);
  if (options.use_response_expansion) {
    double offset = options.coarse_angle_offset;
    for (int i = 0; i < 3; ++i) {
      offset += 20 * kRadiansPerDegree;
      double l = 0.0, h = 0.0;
      LatticeRange(offset, cr, &l, &h);
      lo = std::min(lo, l);
      hi = std::max(hi, h);
    }
  }
  double fine_lo = 0.0, fine_hi = 0.0;
  LatticeRange(0.5 * cr, options.fine_angle_step, &fine_lo, &fine_hi);
  const bool coarse_range_bounded = hi - lo < kPi - 1e-6;
  heading_lo_ = lo + std::min(0.0, fine_lo) - 1e-9;
  heading_hi_ = hi + std::max(0.0, fine_hi) + 1e-9;
  if (coarse_range_bounded) {
    num_buckets_ = std::max(1, static_cast<int>(std::ceil((heading_hi_ - heading_lo_) / cr)));
    bucket_half_ = 0.5 * (heading_hi_ - heading_lo_) / num_buckets_;
    // Centre bucket first: good matches reach the threshold there and stop the count early.
    const int centre = std::clamp(static_cast<int>((0.0 - heading_lo_) / (2 * bucket_half_)), 0, num_buckets_ - 1);
    bucket_order_.push_back(centre);
    for (int d = 1; static_cast<int>(bucket_order_.size()) < num_buckets_; ++d) {
      if (centre + d < num_buckets_) bucket_order_.push_back(centre + d);
      if (centre - d >= 0) bucket_order_.push_back(centre - d);
    }
  }
  // Rounding of the candidate cell and of the table offset (one cell per axis together), of
  // the chain point's cell (half a cell), the kernel's reach h, and half a cell of margin.
  slack_ = (geometry_.kernel_half + 2.5) * resolution_;
  cell_ = kCellsPerBitmapCell * resolution_;
  const double extent = geometry_.stored_side * resolution_;
  side_ = static_cast<int>(std::ceil(extent / cell_)) + 1;
  words_per_row_ = (side_ + 63) / 64;
  bits_.assign(static_cast<std::size_t>(side_) * words_per_row_, 0);
}

const ResponseBound::ScanCells& ResponseBound::CellsOf(const LaserScan& scan) {
  const Pose2 pose = scan.SensorPose();
  ScanCells& entry = scan_cells_[scan.ranges_ptr().get()];
  if (entry.ranges == scan.ranges_ptr() && std::memcmp(&entry.sensor_pose, &pose, sizeof(Pose2)) == 0) {
    return entry;
  }
  entry.ranges = scan.ranges_ptr();
  entry.sensor_pose = pose;
  entry.cells.clear();
  entry.min_x = entry.min_y = std::numeric_limits<std::int32_t>::max();
  entry.max_x = entry.max_y = std::numeric_limits<std::int32_t>::min();
  const double inverse = 1.0 / cell_;
  std::int32_t last_x = 0, last_y = 0;
  bool first = true;
  for (const Eigen::Vector2d& p : scan.unfiltered_points()) {
    const double u = std::floor(p.x() * inverse), v = std::floor(p.y() * inverse);
    // NaN, inf and points beyond any grid (|u| >= 2^30 cells) are never inserted.
    if (!(std::fabs(u) < 1073741824.0 && std::fabs(v) < 1073741824.0)) continue;
    const auto cx = static_cast<std::int32_t>(u), cy = static_cast<std::int32_t>(v);
    if (!first && cx == last_x && cy == last_y) continue;
    entry.cells.push_back(cx);
    entry.cells.push_back(cy);
    entry.min_x = std::min(entry.min_x, cx);
    entry.max_x = std::max(entry.max_x, cx);
    entry.min_y = std::min(entry.min_y, cy);
    entry.max_y = std::max(entry.max_y, cy);
    last_x = cx;
    last_y = cy;
    first = false;
  }
  return entry;
}

void ResponseBound::MarkChain(const LaserScan& scan, std::span<const LaserScan* const> base_scans) {
  // The matcher's ROI placement (§4.2 step 2), so cells line up with the grid it would build.
  const Pose2 sensor = scan.SensorPose();
  origin_ = {sensor.x - (0.5 * (geometry_.roi_side - 1) * resolution_),
             sensor.y - (0.5 * (geometry_.roi_side - 1) * resolution_)};
  stored_lo_ = origin_ - Eigen::Vector2d::Constant((geometry_.border + 0.5) * resolution_);
  if (marked_x0_ <= marked_x1_) {
    for (std::int32_t y = marked_y0_; y <= marked_y1_; ++y) {
      std::fill_n(bits_.begin() + static_cast<std::ptrdiff_t>(y) * words_per_row_, words_per_row_, 0);
    }
  }
  bitmap_x0_ = static_cast<std::int32_t>(std::floor(stored_lo_.x() / cell_));
  bitmap_y0_ = static_cast<std::int32_t>(std::floor(stored_lo_.y() / cell_));
  marked_x0_ = marked_y0_ = side_;
  marked_x1_ = marked_y1_ = -1;
  for (const LaserScan* base : base_scans) {
    SLAMTUNE_CHECK(base != nullptr);
    const ScanCells& scan_cells = CellsOf(*base);
    if (scan_cells.cells.empty()) continue;
    const std::vector<std::int32_t>& cells = scan_cells.cells;
    for (std::size_t i = 0; i < cells.size(); i += 2) {
      // Unsigned compare: negative differences wrap above the bitmap's size.
      const auto cx = static_cast<std::uint32_t>(cells[i] - bitmap_x0_);
      const auto cy = static_cast<std::uint32_t>(cells[i + 1] - bitmap_y0_);
      if (cx >= static_cast<std::uint32_t>(side_) || cy >= static_cast<std::uint32_t>(side_)) continue;
      bits_[static_cast<std::size_t>(cy) * words_per_row_ + (cx >> 6)] |= std::uint64_t{1} << (cx & 63);
    }
    // The scan's box, clipped to the bitmap, bounds what it marked.
    marked_x0_ = std::min(marked_x0_, std::max(0, scan_cells.min_x - bitmap_x0_));
    marked_x1_ = std::max(marked_x1_, std::min(side_ - 1, scan_cells.max_x - bitmap_x0_));
    marked_y0_ = std::min(marked_y0_, std::max(0, scan_cells.min_y - bitmap_y0_));
    marked_y1_ = std::max(marked_y1_, std::min(side_ - 1, scan_cells.max_y - bitmap_y0_));
  }
}

bool ResponseBound::AnyPointIn(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) const {
  // Lattice cells of the box, rounded outwards, then clipped to the marked box.
  const double inverse = 1.0 / cell_;
  const auto x0 = std::max(marked_x0_, static_cast<std::int32_t>(std::floor(lo.x() * inverse)) - bitmap_x0_);
  const auto x1 = std::min(marked_x1_, static_cast<std::int32_t>(std::floor(hi.x() * inverse)) - bitmap_x0_);
  const auto y0 = std::max(marked_y0_, static_cast<std::int32_t>(std::floor(lo.y() * inverse)) - bitmap_y0_);
  const auto y1 = std::min(marked_y1_, static_cast<std::int32_t>(std::floor(hi.y() * inverse)) - bitmap_y0_);
  if (x0 > x1 || y0 > y1) return false;
  const int w0 = x0 >> 6, w1 = x1 >> 6;
  const std::uint64_t first_mask = ~std::uint64_t{0} << (x0 & 63);
  const std::uint64_t last_mask = ~std::uint64_t{0} >> (63 - (x1 & 63));
  for (int y = y0; y <= y1; ++y) {
    const std::uint64_t* row = bits_.data() + static_cast<std::size_t>(y) * words_per_row_;
    for (int w = w0; w <= w1; ++w) {
      std::uint64_t mask = ~std::uint64_t{0};
      if (w == w0) mask &= first_mask;
      if (w == w1) mask &= last_mask;
      if (row[w] & mask) return true;
    }
  }
  return false;
}

int ResponseBound::MaxCount(const LaserScan& scan, int stop_at, Count goal) {
  const Pose2 sensor = scan.SensorPose();
  const std::vector<Eigen::Vector2d>& points = scan.unfiltered_points();
  const std::vector<double>& ranges = scan.ranges();
  // Beam end points in the sensor frame, as the lookup tables take them (§4.4).
  const double inv_c = std::cos(0.0 - sensor.theta), inv_s = std::sin(0.0 - sensor.theta);
  local_.clear();
  reach_.clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::isnan(ranges[i]) || std::isinf(ranges[i])) continue;  // INVALID: never read
    const double dx = points[i].x() - sensor.x, dy = points[i].y() - sensor.y;
    const Eigen::Vector2d l(inv_c * dx - inv_s * dy, inv_s * dx + inv_c * dy);
    local_.push_back(l);
    reach_.push_back(window_ + l.norm() * bucket_half_);
  }
  const int valid = static_cast<int>(local_.size());
  const double rho = resolution_;
  const int border = geometry_.border;
  const std::int64_t stride = geometry_.stride;
  const std::int64_t data_size = geometry_.data_size();
  // Metric box whose reads stay inside the stored grid, one cell inside its edges (so the
  // cheap test needs no division; a beam near an edge takes the exact path below).
  const Eigen::Vector2d inside_lo = origin_ - Eigen::Vector2d::Constant((border - 1) * rho);
  const Eigen::Vector2d inside_hi = origin_ + Eigen::Vector2d::Constant((geometry_.stored_side - border - 2) * rho);
  int best = 0;
  for (const int bucket : bucket_order_) {
    const double heading = sensor.theta + heading_lo_ + (2 * bucket + 1) * bucket_half_;
    const double c = std::cos(heading), s = std::sin(heading);
    int count = 0;
    for (int b = 0; b < valid; ++b) {
      // This bucket can no longer reach stop_at (nor, for the exact maximum, beat the best).
      const int possible = count + (valid - b);
      if (possible < stop_at && (goal != Count::kExactMax || possible <= best)) break;
      const Eigen::Vector2d& l = local_[static_cast<std::size_t>(b)];
      const Eigen::Vector2d q(sensor.x + (c * l.x() - s * l.y()), sensor.y + (s * l.x() + c * l.y()));
      // Stored cells this beam may read at the bucket's poses (§4.5 adds cell and offset).
      const double read = reach_[static_cast<std::size_t>(b)] + 2.0 * rho;
      bool scores;
      if (q.x() - read >= inside_lo.x() && q.x() + read <= inside_hi.x() && q.y() - read >= inside_lo.y() &&
          q.y() + read <= inside_hi.y()) {
        const double h = reach_[static_cast<std::size_t>(b)] + slack_;
        scores = AnyPointIn({q.x() - h, q.y() - h}, {q.x() + h, q.y() + h});
      } else {
        const double gx0 = std::floor((q.x() - read - origin_.x()) / rho) + border;
        const double gx1 = std::ceil((q.x() + read - origin_.x()) / rho) + border;
        const double gy0 = std::floor((q.y() - read - origin_.y()) / rho) + border;
        const double gy1 = std::ceil((q.y() + read - origin_.y()) / rho) + border;
        if (gx0 >= 0 && gx1 < geometry_.stored_side && gy0 >= 0 && gy1 < geometry_.stored_side) {
          const double h = reach_[static_cast<std::size_t>(b)] + slack_;
          scores = AnyPointIn({q.x() - h, q.y() - h}, {q.x() + h, q.y() + h});
        } else {
          // Reads outside the stored grid: Karto's linear index may wrap onto another row, so
          // count the beam, unless every index it can form is outside [0, data size).
          const double lowest = gx0 + gy0 * static_cast<double>(stride);
          const double highest = gx1 + gy1 * static_cast<double>(stride);
          scores = !(highest < 0.0 || lowest >= static_cast<double>(data_size));
        }
      }
      if (scores && ++count >= stop_at) return count;
    }
    best = std::max(best, count);
  }
  return best;
}

bool ResponseBound::MayExceed(const LaserScan& scan, std::span<const LaserScan* const> base_scans, double threshold) {
  const std::size_t beams = scan.ranges().size();
  if (beams == 0) return 0.0 > threshold;  // Match returns response 0 (§4.2 item 1)
  if (num_buckets_ == 0) return true;
  // The smallest beam count whose sum the matcher would turn into a response above the
  // threshold, with the matcher's own division (sum / (100 beams), §4.5).
  const double divisor = static_cast<double>(static_cast<std::uint32_t>(beams) * 100u);
  int needed = std::max(0, static_cast<int>(std::floor(threshold * static_cast<double>(beams))) - 1);
  while (needed <= static_cast<int>(beams) && !(static_cast<double>(needed) * 100.0 / divisor > threshold)) ++needed;
  if (needed > static_cast<int>(beams)) return false;  // even every beam at 100 stays <= threshold
  MarkChain(scan, base_scans);
  return MaxCount(scan, needed, Count::kUntilStopAt) >= needed;
}

std::int64_t ResponseBound::MaxSumBound(const LaserScan& scan, std::span<const LaserScan* const> base_scans) {
  const std::size_t beams = scan.ranges().size();
  if (beams == 0) return 0;
  if (num_buckets_ == 0) return static_cast<std::int64_t>(beams) * 100;
  MarkChain(scan, base_scans);
  return static_cast<std::int64_t>(MaxCount(scan, static_cast<int>(beams) + 1, Count::kExactMax)) * 100;
}

}  // namespace slamtune::slam
