#include "slamtune/sim/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::sim {
namespace {

double Cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// Liang–Barsky clip of the segment p + s (q - p), s in [0, 1], against the box [lo, hi]:
// true when some part of the segment lies in the box (boundary included).
bool SegmentTouchesBox(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& lo,
                       const Eigen::Vector2d& hi) {
  double s0 = 0.0, s1 = 1.0;
  const Eigen::Vector2d d = q - p;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double a = (lo[axis] - p[axis]) / d[axis];
    double b = (hi[axis] - p[axis]) / d[axis];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
    if (s0 > s1) return false;
  }
  return true;
}

}  // namespace

std::optional<double> IntersectRay(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                                   const Segment& segment) {
  // origin + t d = a + u (b - a): Cramer's rule on the 2x2 system.
  const Eigen::Vector2d edge = segment.b - segment.a;
  const double denominator = Cross(direction, edge);
  if (denominator == 0.0) return std::nullopt;
  const Eigen::Vector2d to_a = segment.a - origin;
  const double t = Cross(to_a, edge) / denominator;
  const double u = Cross(to_a, direction) / denominator;
  if (t < 0.0 || u < 0.0 || u > 1.0) return std::nullopt;
  return t;
}

RayCaster::RayCaster(std::vector<Segment> segments, double cell_size)
    : segments_(std::move(segments)), cell_size_(cell_size) {
  SLAMTUNE_CHECK_MSG(cell_size_ > 0.0, "cell size must be positive");
  if (segments_.empty()) return;
  Eigen::Vector2d lo = segments_.front().a, hi = lo;
  for (const Segment& s : segments_) {
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
  }
  // One spare cell on every side so that walls on the outline lie strictly inside the grid.
  min_ = lo - Eigen::Vector2d::Constant(cell_size_);
  nx_ = static_cast<int>(std::ceil((hi.x() - min_.x()) / cell_size_)) + 1;
  ny_ = static_cast<int>(std::ceil((hi.y() - min_.y()) / cell_size_)) + 1;

  // List each segment in every cell it touches. Boxes are widened by a hair and the candidate
  // range by one cell, so a wall lying exactly on a cell boundary is listed on both sides
  // whatever the rounding of the cell arithmetic.
  std::vector<std::vector<int>> lists(static_cast<std::size_t>(nx_) * ny_);
  const Eigen::Vector2d hair = Eigen::Vector2d::Constant(1e-9 * cell_size_);
  const auto cell_of = [&](double v, double origin, int count) {
    return std::clamp(static_cast<int>(std::floor((v - origin) / cell_size_)), 0, count - 1);
  };
  for (int index = 0; index < static_cast<int>(segments_.size()); ++index) {
    const Segment& s = segments_[index];
    const Eigen::Vector2d smin = s.a.cwiseMin(s.b), smax = s.a.cwiseMax(s.b);
    const int x0 = std::max(cell_of(smin.x(), min_.x(), nx_) - 1, 0);
    const int x1 = std::min(cell_of(smax.x(), min_.x(), nx_) + 1, nx_ - 1);
    const int y0 = std::max(cell_of(smin.y(), min_.y(), ny_) - 1, 0);
    const int y1 = std::min(cell_of(smax.y(), min_.y(), ny_) + 1, ny_ - 1);
    for (int cy = y0; cy <= y1; ++cy) {
      for (int cx = x0; cx <= x1; ++cx) {
        const Eigen::Vector2d cell_lo = min_ + cell_size_ * Eigen::Vector2d(cx, cy);
        const Eigen::Vector2d cell_hi = cell_lo + Eigen::Vector2d::Constant(cell_size_);
        if (SegmentTouchesBox(s.a, s.b, cell_lo - hair, cell_hi + hair)) {
          lists[static_cast<std::size_t>(cy) * nx_ + cx].push_back(index);
        }
      }
    }
  }
  cell_start_.assign(lists.size() + 1, 0);
  for (std::size_t c = 0; c < lists.size(); ++c) cell_start_[c + 1] = cell_start_[c] + lists[c].size();
  cell_items_.reserve(cell_start_.back());
  for (const auto& list : lists) cell_items_.insert(cell_items_.end(), list.begin(), list.end());
}

std::optional<double> RayCaster::Cast(const Eigen::Vector2d& origin, double angle, double max_range) const {
  if (segments_.empty()) return std::nullopt;
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  constexpr double kInf = std::numeric_limits<double>::infinity();

  // Clip the ray to the grid box; every wall lies inside it.
  const Eigen::Vector2d grid_max = min_ + cell_size_ * Eigen::Vector2d(nx_, ny_);
  double t_enter = 0.0, t_leave = max_range;
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] == 0.0) {
      if (origin[axis] < min_[axis] || origin[axis] > grid_max[axis]) return std::nullopt;
      continue;
    }
    double a = (min_[axis] - origin[axis]) / direction[axis];
    double b = (grid_max[axis] - origin[axis]) / direction[axis];
    if (a > b) std::swap(a, b);
    t_enter = std::max(t_enter, a);
    t_leave = std::min(t_leave, b);
  }
  if (t_enter > t_leave) return std::nullopt;

  // Amanatides–Woo traversal from the entry point.
  const Eigen::Vector2d start = origin + t_enter * direction;
  int cell[2], step[2];
  double t_next[2], t_delta[2];
  const int counts[2] = {nx_, ny_};
  for (int axis = 0; axis < 2; ++axis) {
    const double local = (start[axis] - min_[axis]) / cell_size_;
    cell[axis] = std::clamp(static_cast<int>(std::floor(local)), 0, counts[axis] - 1);
    if (direction[axis] > 0.0) {
      step[axis] = 1;
      t_next[axis] = (min_[axis] + (cell[axis] + 1) * cell_size_ - origin[axis]) / direction[axis];
      t_delta[axis] = cell_size_ / direction[axis];
    } else if (direction[axis] < 0.0) {
      step[axis] = -1;
      t_next[axis] = (min_[axis] + cell[axis] * cell_size_ - origin[axis]) / direction[axis];
      t_delta[axis] = -cell_size_ / direction[axis];
    } else {
      step[axis] = 0;
      t_next[axis] = kInf;
      t_delta[axis] = kInf;
    }
  }

  double best = kInf;
  while (true) {
    const std::size_t c = static_cast<std::size_t>(cell[1]) * nx_ + cell[0];
    for (std::size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
      const auto t = IntersectRay(origin, direction, segments_[cell_items_[k]]);
      if (t && *t < best) best = *t;
    }
    const int axis = t_next[0] < t_next[1] ? 0 : 1;
    const double t_exit = t_next[axis];
    // Hits in later cells are at least t_exit away, so a nearer hit is final.
    if (best <= t_exit || t_exit > t_leave) break;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= counts[axis]) break;
    t_next[axis] += t_delta[axis];
  }
  if (best <= max_range) return best;
  return std::nullopt;
}

}  // namespace slamtune::sim
