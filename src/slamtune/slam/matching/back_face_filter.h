// Karto's back-face filter (docs/engine.md §4.3, "valid points"): before a base scan is
// drawn into the correlation grid, drop the stretches of its outline that the scan being
// matched would see from behind. What remains is what a sensor standing at the viewpoint
// could plausibly observe, so surfaces seen only from their back side cannot attract the
// match.
//
// The rule walks the base scan's *unfiltered* points in beam order with an anchor point F
// (the last point at least 10 cm from the previous anchor) and a pending-start index t:
// when a point C lies more than 10 cm from F, the sign of the cross product
// (F - V) x (C - V) decides whether the stretch t .. C-1 is kept (>= 0) or dropped (< 0).
// NaN and +-inf readings propagate through Karto's exact arithmetic (docs/engine.md §4.3), so a NaN
// distance never opens a new stretch and a NaN side test counts as "keep"; the points after
// the last anchor are never output. Non-finite points may reach the output; the grid
// insertion drops them (§4.3, last item).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace slamtune::slam {

// Calls visit(point) for every point that passes the back-face filter seen from
// `viewpoint` (§4.3), in beam order. Inline so that the grid can draw the points as they come
// instead of collecting them first.
template <typename Visit>
void ForEachValidPoint(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& viewpoint, Visit&& visit) {
  // Karto squares 0.1 in double arithmetic; 0.1 * 0.1 is 0.010000000000000002, not 0.01, and
  // we keep that exact threshold (§4.3 "10 cm").
  const double min_squared_distance = 0.1 * 0.1;
  const double vx = viewpoint.x(), vy = viewpoint.y();
  // Anchor F: (0, 0) until the first point whose x and y are both not NaN (an inf point can
  // be the anchor, §4.3 [QUIRK]).
  double fx = 0.0, fy = 0.0;
  bool anchor_set = false;
  std::size_t pending_start = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double cx = points[i].x(), cy = points[i].y();
    if (!anchor_set && !std::isnan(cx) && !std::isnan(cy)) {
      fx = cx;
      fy = cy;
      anchor_set = true;
    }
    const double dx = fx - cx, dy = fy - cy;
    // A NaN squared distance compares false: the point neither opens nor closes a stretch.
    if (!(dx * dx + dy * dy > min_squared_distance)) continue;
    // s = z component of (F - V) x (C - V), in Karto's exact expression so that NaN and inf
    // propagate identically (§4.3).
    const double a = vy - fy;
    const double b = fx - vx;
    const double c = fy * vx - fx * vy;
    const double s = cx * a + cy * b + c;
    fx = cx;
    fy = cy;
    // Seen from behind (s < 0): drop the pending stretch. Otherwise (including NaN, which is
    // "not < 0") output it. Either way a new stretch starts at C.
    if (!(s < 0.0)) {
      for (std::size_t k = pending_start; k < i; ++k) visit(points[k]);
    }
    pending_start = i;
  }
}

// Appends to `*valid` (cleared first) the points of `points` (a scan's unfiltered list, beam
// order) that pass the back-face filter seen from `viewpoint` (§4.3). `valid` is an output
// buffer so callers can reuse its capacity between scans.
void FilterBackFaces(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& viewpoint,
                     std::vector<Eigen::Vector2d>* valid);

// Convenience form returning a new vector.
std::vector<Eigen::Vector2d> FilterBackFaces(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& viewpoint);

}  // namespace slamtune::slam
