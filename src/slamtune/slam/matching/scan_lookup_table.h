// Per-angle lookup tables of the scan matcher (docs/engine.md §4.4): for each candidate
// heading, the linear grid offset (dx + dy*stride) of every beam's end point relative to the
// candidate cell, so that scoring a candidate is a sum of byte reads (§4.5).
//
// Karto builds the tables from the scan's *unfiltered* points expressed in the frame of its
// current sensor pose; only NaN/inf readings get the INVALID marker, while finite readings
// below minRange or beyond the range threshold are used (§2.2 [QUIRK]). Every beam has an
// entry, so the response divisor counts all beams.
//
// Partition() then sorts the valid entries of each angle, for a given range of candidate
// indices, into "safe" offsets (in [0, size) for every candidate, no test needed) and
// "checked" offsets (far points whose summed index may leave the grid, tested per
// candidate as in §4.5). This is only a reordering of integer additions, so sums are exact.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam {

// Marker for beams whose reading is NaN or +-inf (§4.4). Also used for finite points so far
// away that their linear offset does not fit 32 bits; such a point can never be in range.
inline constexpr std::int32_t kInvalidLookup = std::numeric_limits<std::int32_t>::max();

class ScanLookupTable {
 public:
  // Fills the tables for K = Round(2 angle_offset / angle_step) + 1 headings
  // alpha_k = (angle_center - angle_offset) + k angle_step (§4.4). `grid_origin`, `scale` and
  // `stride` are those of the correlation grid (Karto converts offset + origin back through
  // the grid's WorldToGrid; replicated).
  void Compute(const LaserScan& scan, double angle_center, double angle_offset, double angle_step,
               const Eigen::Vector2d& grid_origin, double scale, std::int32_t stride);

  int num_angles() const { return static_cast<int>(angles_.size()); }
  // Number of beams of the scan: the response divisor counts all of them (§4.5).
  int num_beams() const { return num_beams_; }
  // Absolute heading alpha_k (not normalised).
  double angle(int k) const { return angles_[static_cast<std::size_t>(k)]; }
  // One entry per beam for heading k: a linear offset or kInvalidLookup.
  std::span<const std::int32_t> offsets(int k) const {
    return {offsets_.data() + static_cast<std::size_t>(k) * num_beams_, static_cast<std::size_t>(num_beams_)};
  }

  // Splits the valid entries of every heading for candidate cell indices in
  // [min_index, max_index] and a grid of `data_size` cells (see the file comment).
  void Partition(std::int64_t min_index, std::int64_t max_index, std::int64_t data_size);
  std::span<const std::int32_t> safe_offsets(int k) const { return Slice(safe_, safe_begin_, k); }
  std::span<const std::int32_t> checked_offsets(int k) const { return Slice(checked_, checked_begin_, k); }

 private:
  static std::span<const std::int32_t> Slice(const std::vector<std::int32_t>& v, const std::vector<std::size_t>& begin,
                                             int k) {
    const std::size_t b = begin[static_cast<std::size_t>(k)], e = begin[static_cast<std::size_t>(k) + 1];
    return {v.data() + b, e - b};
  }

  int num_beams_ = 0;
  std::vector<double> angles_;
  std::vector<std::int32_t> offsets_;          // K x num_beams, heading-major
  std::vector<Eigen::Vector2d> local_points_;  // scratch: points in the sensor frame
  std::vector<std::uint8_t> invalid_;          // scratch: reading is NaN or +-inf
  // Inputs of the tables in offsets_ (Compute skips the work when they repeat bit for bit).
  bool computed_ = false;
  double inputs_[7] = {};
  std::vector<Eigen::Vector2d> previous_local_points_;
  std::vector<std::uint8_t> previous_invalid_;
  std::vector<std::int32_t> safe_, checked_;
  std::vector<std::size_t> safe_begin_, checked_begin_;  // K + 1 boundaries each
};

}  // namespace slamtune::slam
