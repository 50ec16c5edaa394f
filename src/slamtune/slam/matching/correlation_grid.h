// The correlation grid of Karto's scan matcher (docs/engine.md §4.1, §4.3): a byte grid
// at the matcher's resolution rho, holding 100 at cells hit by a base-scan point and a
// Gaussian "smear" around them, against which candidate poses of the scan are scored (§4.5).
//
// Geometry (§4.1): the search window has n = Round(D/rho) + 1 cells per side; a margin of
// m = ceil(Rt/rho) cells keeps every in-range point of a candidate inside the grid, so the
// region of interest (ROI) is G = n + 2m cells per side; a border b = h + 1 (h = kernel
// half-size) lets the smear spill over the ROI edge. Rows are stored with a stride rounded
// up to a multiple of 8 (§1.2), and linear indices x + y*stride are what the lookup tables of
// §4.4 add to candidate cells.
//
// The grid is reused across matches: Clear() zeroes only what was written since the last
// clear (the kernel squares of the inserted points, or their bounding box when that is
// smaller), which keeps a 6 MB sequential grid cheap to rebuild for every scan.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam {

// Cell value of a point hit ("occupied" in Karto's correlation grid, §1.1).
inline constexpr std::uint8_t kCorrelationOccupied = 100;

// The sizes of §4.1, all in cells.
struct CorrelationGridGeometry {
  int search_side = 0;  // n = Round(D/rho) + 1
  int margin = 0;       // m = ceil(Rt/rho)
  int roi_side = 0;     // G = n + 2m
  int kernel_half = 0;  // h = Round(2 sigma/rho); the kernel is (2h+1)^2
  int border = 0;       // b = h + 1
  int stored_side = 0;  // G + 2b (width and height of the stored grid)
  int stride = 0;       // stored_side rounded up to a multiple of 8

  // Computes the table of §4.1 from the matcher parameters (metres). Inputs are assumed
  // valid (ScanMatcherOptions::Validate).
  static CorrelationGridGeometry Compute(double search_dimension, double resolution, double smear_deviation,
                                         double range_threshold);
  // stride * stored_side: the size of the linear index space of §4.5.
  std::int64_t data_size() const { return static_cast<std::int64_t>(stride) * stored_side; }
};

// The smearing kernel of §4.1: side 2h+1, value Round(100 exp(-0.5 (d/sigma)^2)) at cell
// offset (i, j) with d the metric distance; stored row-major, index (i+h) + (2h+1)(j+h).
std::vector<std::uint8_t> MakeSmearKernel(double smear_deviation, double resolution);

class CorrelationGrid {
 public:
  CorrelationGrid(double search_dimension, double resolution, double smear_deviation, double range_threshold);

  const CorrelationGridGeometry& geometry() const { return geometry_; }
  double resolution() const { return resolution_; }
  // 1/resolution, computed once; world->grid multiplies by it (§1.2).
  double scale() const { return scale_; }

  // World position of ROI cell (0, 0). MatchScan places it at c - (G-1)/2 rho (§4.2 step 2).
  void SetRoiOrigin(const Eigen::Vector2d& origin) { roi_origin_ = origin; }
  const Eigen::Vector2d& roi_origin() const { return roi_origin_; }

  // ROI-relative cell of a world point: Round((w - origin) * scale) per axis (§1.2).
  Eigen::Vector2i WorldToGrid(const Eigen::Vector2d& world) const;
  // Stored linear index of a ROI-relative cell (border added). The cell must lie in the
  // stored grid (checked).
  std::int32_t GridIndex(const Eigen::Vector2i& roi_cell) const;

  // Zeroes every cell written since the previous Clear (all cells start at zero).
  void Clear();
  // Builds the grid from base scans as seen from `viewpoint` (§4.3): clear, then for each
  // scan in the given order its back-face-filtered unfiltered points in beam order. The bytes
  // are those of that order; when no kernel value off the centre is 100 (so that order cannot
  // matter) the cells are inserted row by row instead, which keeps the smeared rows in cache.
  void AddScans(std::span<const LaserScan* const> base_scans, const Eigen::Vector2d& viewpoint);
  // Inserts one world point (§4.3): skipped if not finite, outside the ROI or already 100;
  // otherwise set to 100 and smeared by max-merge. Returns whether the cell was set.
  bool AddPoint(const Eigen::Vector2d& world);

  // Raw storage: data_size() bytes, followed by kPadding zero bytes that the vectorised
  // search may read past the last candidate byte (never counted).
  const std::uint8_t* data() const { return data_.data(); }
  std::int32_t data_size() const { return static_cast<std::int32_t>(geometry_.data_size()); }
  // Value of a ROI-relative cell (may address the border: -b <= x, y < G + b).
  std::uint8_t ValueAt(int roi_x, int roi_y) const;

  std::span<const std::uint8_t> kernel() const { return kernel_; }

  // Zero bytes after the grid; at least 64 for the search kernel and a padded kernel row.
  static constexpr int kPadding = 64;

 private:
  // The stored cell of a world point, or false if outside the ROI or not finite (§4.3).
  bool CellOf(const Eigen::Vector2d& world, int* stored_x, int* stored_y) const;
  // Sets a stored cell to 100 and smears it, unless it already holds 100 (§4.3).
  bool InsertCell(int stored_x, int stored_y);
  // Max-merges the kernel centred on a stored linear index.
  void Smear(std::int32_t centre);
  void Touch(int x0, int y0, int x1, int y1) {
    touched_x0_ = std::min(touched_x0_, x0);
    touched_y0_ = std::min(touched_y0_, y0);
    touched_x1_ = std::max(touched_x1_, x1);
    touched_y1_ = std::max(touched_y1_, y1);
  }

  CorrelationGridGeometry geometry_;
  double resolution_;
  double scale_;
  Eigen::Vector2d roi_origin_{0, 0};
  std::vector<std::uint8_t> kernel_;
  // Kernel rows padded with zeros to a multiple of 16 bytes, so that the max-merge runs on
  // whole vectors (a zero leaves the grid byte unchanged).
  int padded_side_;
  std::vector<std::uint8_t> padded_kernel_;
  std::vector<std::uint8_t> data_;
  // Stored-grid box written since the last Clear (empty when x0 > x1), and the centres of
  // the kernels written into it: Clear zeroes those kernel squares when that is less work
  // than zeroing the box.
  int touched_x0_, touched_y0_, touched_x1_, touched_y1_;
  std::vector<std::int32_t> smeared_centres_;
  // AddScans' row-ordered insertion: the stored cells of the points, the same sorted by row,
  // and the counting sort's row offsets. order_free_: no kernel value off the centre is 100.
  struct HitCell {
    int x, y;
  };
  bool order_free_ = false;
  std::vector<HitCell> hit_cells_, sorted_cells_;
  std::vector<std::int32_t> row_starts_;
};

}  // namespace slamtune::slam
