// Karto's back-face filter (karto-algorithm.md §4.3, "valid points"): before a base scan is
// drawn into the correlation grid, drop the stretches of its outline that the scan being
// matched would see from behind. What remains is what a sensor standing at the viewpoint
// could plausibly observe, so surfaces seen only from their back side cannot attract the
// match.
//
// The rule walks the base scan's *unfiltered* points in beam order with an anchor point F
// (the last point at least 10 cm from the previous anchor) and a pending-start index t:
// when a point C lies more than 10 cm from F, the sign of the cross product
// (F - V) x (C - V) decides whether the stretch t .. C-1 is kept (>= 0) or dropped (< 0).
// NaN and +-inf readings propagate through the exact arithmetic of the spec, so a NaN
// distance never opens a new stretch and a NaN side test counts as "keep"; the points after
// the last anchor are never output. Non-finite points may reach the output; the grid
// insertion drops them (§4.3, last item).
#pragma once

#include <Eigen/Core>

#include <span>
#include <vector>

namespace slamtune::slam {

// Appends to `*valid` (cleared first) the points of `points` (a scan's unfiltered list, beam
// order) that pass the back-face filter seen from `viewpoint` (§4.3). `valid` is an output
// buffer so callers can reuse its capacity between scans.
void FilterBackFaces(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& viewpoint,
                     std::vector<Eigen::Vector2d>* valid);

// Convenience form returning a new vector.
std::vector<Eigen::Vector2d> FilterBackFaces(std::span<const Eigen::Vector2d> points,
                                             const Eigen::Vector2d& viewpoint);

}  // namespace slamtune::slam
