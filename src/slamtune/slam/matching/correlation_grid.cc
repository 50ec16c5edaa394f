#include "slamtune/slam/matching/correlation_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/slam/matching/back_face_filter.h"

namespace slamtune::slam {
namespace {

int AlignTo8(int v) { return (v + 7) & ~7; }

}  // namespace

CorrelationGridGeometry CorrelationGridGeometry::Compute(double search_dimension, double resolution,
                                                         double smear_deviation, double range_threshold) {
  // §4.1 table; every quantity is in cells.
  CorrelationGridGeometry g;
  g.search_side = KartoRoundToInt(search_dimension / resolution) + 1;
  g.margin = static_cast<int>(std::ceil(range_threshold / resolution));
  g.roi_side = g.search_side + 2 * g.margin;
  g.kernel_half = KartoRoundToInt(2.0 * smear_deviation / resolution);
  g.border = g.kernel_half + 1;
  g.stored_side = g.roi_side + 2 * g.border;
  g.stride = AlignTo8(g.stored_side);
  return g;
}

std::vector<std::uint8_t> MakeSmearKernel(double smear_deviation, double resolution) {
  const int half = KartoRoundToInt(2.0 * smear_deviation / resolution);
  const int side = 2 * half + 1;
  std::vector<std::uint8_t> kernel(static_cast<std::size_t>(side) * side);
  for (int j = -half; j <= half; ++j) {
    for (int i = -half; i <= half; ++i) {
      // §4.1: Round(100 exp(-0.5 (d/sigma)^2)), d = rho sqrt(i^2 + j^2). Evaluated as Karto
      // does (hypot of the metric offsets, pow(., 2)) so that no value near .5 can round
      // differently.
      const double distance = std::hypot(i * resolution, j * resolution);
      const double z = std::exp(-0.5 * std::pow(distance / smear_deviation, 2));
      const double value = KartoRound(z * kCorrelationOccupied);
      SLAMTUNE_CHECK(value >= 0.0 && value <= 255.0);
      kernel[static_cast<std::size_t>((i + half) + side * (j + half))] = static_cast<std::uint8_t>(value);
    }
  }
  return kernel;
}

CorrelationGrid::CorrelationGrid(double search_dimension, double resolution, double smear_deviation,
                                 double range_threshold)
    : geometry_(CorrelationGridGeometry::Compute(search_dimension, resolution, smear_deviation, range_threshold)),
      resolution_(resolution),
      scale_(1.0 / resolution),
      // Karto computes the kernel from the grid's resolution read back as 1/scale (the
      // same value as rho for the usual resolutions); the half-size of the border from rho.
      kernel_(MakeSmearKernel(smear_deviation, 1.0 / scale_)) {
  SLAMTUNE_CHECK(kernel_.size() ==
                 static_cast<std::size_t>((2 * geometry_.kernel_half + 1) * (2 * geometry_.kernel_half + 1)));
  const int side = 2 * geometry_.kernel_half + 1;
  padded_side_ = (side + 15) / 16 * 16;
  padded_kernel_.assign(static_cast<std::size_t>(padded_side_) * side, 0);
  for (int j = 0; j < side; ++j) {
    std::copy_n(kernel_.begin() + static_cast<std::ptrdiff_t>(j) * side, side,
                padded_kernel_.begin() + static_cast<std::ptrdiff_t>(j) * padded_side_);
  }
  // A padded row starting at the left end of the kernel may run past the stored grid's last
  // row; the padding absorbs it (the bytes there stay zero: max(0, 0)).
  const std::int64_t padding = std::max<std::int64_t>(kPadding, padded_side_);
  SLAMTUNE_CHECK(geometry_.data_size() + padding < std::numeric_limits<std::int32_t>::max());
  data_.assign(static_cast<std::size_t>(geometry_.data_size() + padding), 0);
  // The centre is always 100; order_free_ when no other value is.
  order_free_ =
      std::count_if(kernel_.begin(), kernel_.end(), [](std::uint8_t v) { return v >= kCorrelationOccupied; }) == 1;
  row_starts_.assign(static_cast<std::size_t>(geometry_.stored_side) + 1, 0);
  touched_x0_ = touched_y0_ = std::numeric_limits<int>::max();
  touched_x1_ = touched_y1_ = std::numeric_limits<int>::min();
}

Eigen::Vector2i CorrelationGrid::WorldToGrid(const Eigen::Vector2d& world) const {
  return {KartoRoundToInt((world.x() - roi_origin_.x()) * scale_),
          KartoRoundToInt((world.y() - roi_origin_.y()) * scale_)};
}

std::int32_t CorrelationGrid::GridIndex(const Eigen::Vector2i& roi_cell) const {
  const int x = roi_cell.x() + geometry_.border;
  const int y = roi_cell.y() + geometry_.border;
  SLAMTUNE_CHECK_MSG(x >= 0 && x < geometry_.stored_side && y >= 0 && y < geometry_.stored_side,
                     "correlation grid cell out of range");
  return x + y * geometry_.stride;
}

std::uint8_t CorrelationGrid::ValueAt(int roi_x, int roi_y) const {
  return data_[static_cast<std::size_t>(GridIndex({roi_x, roi_y}))];
}

void CorrelationGrid::Clear() {
  if (touched_x0_ > touched_x1_) return;
  const std::size_t width = static_cast<std::size_t>(touched_x1_ - touched_x0_ + 1);
  const std::size_t box = width * static_cast<std::size_t>(touched_y1_ - touched_y0_ + 1);
  const int half = geometry_.kernel_half;
  const std::size_t side = static_cast<std::size_t>(2 * half + 1);
  // Locals: the stores below could alias the members as far as the compiler knows.
  const std::ptrdiff_t stride = geometry_.stride;
  const int padded_side = padded_side_;
  std::uint8_t* const data = data_.data();
  if (smeared_centres_.size() * side * static_cast<std::size_t>(padded_side) < box) {
    // Zero each written kernel square, in the padded 16-byte chunks Smear used: every
    // non-zero byte lies in one of these squares, and the extra bytes of a padded row are
    // either zero or inside another square of the list.
    for (const std::int32_t centre : smeared_centres_) {
      std::uint8_t* row = data + (centre - half - half * stride);
      for (std::size_t j = 0; j < side; ++j, row += stride) {
        for (int i0 = 0; i0 < padded_side; i0 += 16) std::memset(row + i0, 0, 16);
      }
    }
  } else {
    for (int y = touched_y0_; y <= touched_y1_; ++y) {
      std::memset(data + (touched_x0_ + y * stride), 0, width);
    }
  }
  smeared_centres_.clear();
  touched_x0_ = touched_y0_ = std::numeric_limits<int>::max();
  touched_x1_ = touched_y1_ = std::numeric_limits<int>::min();
}

void CorrelationGrid::Smear(std::int32_t centre) {
  // Max-merge of the kernel centred on the cell (§4.3); the border b = h + 1 keeps every
  // kernel cell inside the stored grid for any ROI cell.
  const int half = geometry_.kernel_half;
  const int side = 2 * half + 1;
  const std::ptrdiff_t stride = geometry_.stride;
  const int padded_side = padded_side_;
  std::uint8_t* row = data_.data() + (centre - half - half * stride);
  const std::uint8_t* k = padded_kernel_.data();
  for (int j = 0; j < side; ++j, row += stride, k += padded_side) {
    // Whole 16-byte chunks; bytes past the kernel's edge meet zeros and keep their value.
    for (int i0 = 0; i0 < padded_side; i0 += 16) {
#if defined(__SSE2__)
      // Explicit unsigned byte max: GCC keeps the loop below scalar (row and kernel may alias).
      __m128i* dst = reinterpret_cast<__m128i*>(row + i0);
      const __m128i src = _mm_loadu_si128(reinterpret_cast<const __m128i*>(k + i0));
      _mm_storeu_si128(dst, _mm_max_epu8(_mm_loadu_si128(dst), src));
#else
      for (int i = i0; i < i0 + 16; ++i) row[i] = std::max(row[i], k[i]);
#endif
    }
  }
}

bool CorrelationGrid::CellOf(const Eigen::Vector2d& world, int* stored_x, int* stored_y) const {
  // Karto rounds half away from zero and then tests 0 <= cell < G (§1.2, §4.3); Karto casts
  // non-finite coordinates to int, we reject them. The same decision and cell without floor
  // or ceil (baseline x86-64 has no instruction for them; GCC emits several): for v >= 0,
  // Round(v) = trunc(v + 0.5), and that is < G exactly when v + 0.5 < G; for v < 0,
  // Round(v) = ceil(v - 0.5) is in range only when it is 0, that is when v - 0.5 > -1. NaN
  // and inf fail every test.
  const int side = geometry_.roi_side;
  auto axis = [side](double v, int* cell) {
    if (v >= 0.0) {
      const double u = v + 0.5;
      if (!(u < side)) return false;
      *cell = static_cast<int>(u);
      return true;
    }
    if (!(v - 0.5 > -1.0)) return false;
    *cell = 0;
    return true;
  };
  int gx, gy;
  if (!axis((world.x() - roi_origin_.x()) * scale_, &gx) || !axis((world.y() - roi_origin_.y()) * scale_, &gy)) {
    return false;
  }
  *stored_x = gx + geometry_.border;
  *stored_y = gy + geometry_.border;
  return true;
}

bool CorrelationGrid::InsertCell(int stored_x, int stored_y) {
  const std::int32_t index = stored_x + stored_y * geometry_.stride;
  std::uint8_t& cell = data_[static_cast<std::size_t>(index)];
  // "Already 100 -> skip, no smear" (§4.3 [QUIRK]): a kernel value may have rounded to 100.
  if (cell == kCorrelationOccupied) return false;
  cell = kCorrelationOccupied;
  Smear(index);
  smeared_centres_.push_back(index);
  const int half = geometry_.kernel_half;
  Touch(stored_x - half, stored_y - half, stored_x + half, stored_y + half);
  return true;
}

bool CorrelationGrid::AddPoint(const Eigen::Vector2d& world) {
  int x, y;
  return CellOf(world, &x, &y) && InsertCell(x, y);
}

void CorrelationGrid::AddScans(std::span<const LaserScan* const> base_scans, const Eigen::Vector2d& viewpoint) {
  Clear();
  auto for_each_point = [&](auto&& visit) {
    for (const LaserScan* scan : base_scans) {
      SLAMTUNE_CHECK(scan != nullptr);
      ForEachValidPoint(scan->unfiltered_points(), viewpoint, visit);
    }
  };
  if (!order_free_) {
    for_each_point([this](const Eigen::Vector2d& p) { AddPoint(p); });
    return;
  }
  // Every kernel value off the centre is below 100, so a cell holds 100 only where a point was
  // inserted: the "already 100" skip drops exact repeats only and the grid is the max-merge of
  // the kernels of the distinct cells, in any order. Inserting them row by row (a stable
  // counting sort on the stored row) keeps the rows being smeared in the cache.
  hit_cells_.clear();
  for_each_point([this](const Eigen::Vector2d& p) {
    int x, y;
    if (CellOf(p, &x, &y)) hit_cells_.push_back({x, y});
  });
  if (hit_cells_.empty()) return;
  // row_starts_[y] counts the cells of rows below y, then serves as row y's next free slot.
  std::fill(row_starts_.begin(), row_starts_.end(), 0);
  for (const HitCell& c : hit_cells_) ++row_starts_[static_cast<std::size_t>(c.y) + 1];
  for (std::size_t y = 1; y < row_starts_.size(); ++y) row_starts_[y] += row_starts_[y - 1];
  sorted_cells_.resize(hit_cells_.size());
  for (const HitCell& c : hit_cells_) {
    std::int32_t& slot = row_starts_[static_cast<std::size_t>(c.y)];
    sorted_cells_[static_cast<std::size_t>(slot++)] = c;
  }
  for (const HitCell& c : sorted_cells_) InsertCell(c.x, c.y);
}

}  // namespace slamtune::slam
