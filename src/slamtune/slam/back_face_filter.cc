#include "slamtune/slam/back_face_filter.h"

#include <cmath>
#include <cstddef>

#include "slamtune/common/error.h"

namespace slamtune::slam {

void FilterBackFaces(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& viewpoint,
                     std::vector<Eigen::Vector2d>* valid) {
  SLAMTUNE_CHECK(valid != nullptr);
  valid->clear();
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
    // s = z component of (F - V) x (C - V), in the spec's exact expression so that NaN and inf
    // propagate identically (§4.3).
    const double a = vy - fy;
    const double b = fx - vx;
    const double c = fy * vx - fx * vy;
    const double s = cx * a + cy * b + c;
    fx = cx;
    fy = cy;
    if (s < 0.0) {
      // Seen from behind: drop the pending stretch, start a new one at C.
      pending_start = i;
    } else {
      // Seen from the front (or NaN, which is "not < 0"): output pending .. C-1.
      for (std::size_t k = pending_start; k < i; ++k) valid->push_back(points[k]);
      pending_start = i;
    }
  }
}

std::vector<Eigen::Vector2d> FilterBackFaces(std::span<const Eigen::Vector2d> points,
                                             const Eigen::Vector2d& viewpoint) {
  std::vector<Eigen::Vector2d> valid;
  FilterBackFaces(points, viewpoint, &valid);
  return valid;
}

}  // namespace slamtune::slam
