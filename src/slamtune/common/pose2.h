// 2D rigid pose (x, y, theta) with Karto's composition rules (docs/engine.md §1.4).
//
// A Pose2 is a plain value. Compose(A, B) is A (+) B; Between(A, B) is B seen from A,
// i.e. A (-) B in the notation of docs/engine.md §1.4. Angles are kept in [-pi, pi] by NormalizeAngle.
#pragma once

#include <cmath>
#include <string>

#include "slamtune/common/karto_math.h"

namespace slamtune {

struct Pose2 {
  double x = 0.0;      // metres
  double y = 0.0;      // metres
  double theta = 0.0;  // radians

  friend bool operator==(const Pose2&, const Pose2&) = default;
};

// A (+) B = (A.xy + R(A.theta) B.xy, normalize(A.theta + B.theta)).
inline Pose2 Compose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, NormalizeAngle(a.theta + b.theta)};
}

// B seen from A: (R(-A.theta)(B.xy - A.xy), normalize(B.theta - A.theta)).
inline Pose2 Between(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double dx = b.x - a.x, dy = b.y - a.y;
  return {c * dx + s * dy, -s * dx + c * dy, NormalizeAngle(b.theta - a.theta)};
}

// Inverse pose: Compose(p, Inverse(p)) == identity.
inline Pose2 Inverse(const Pose2& p) { return Between(p, Pose2{}); }

// Squared Euclidean distance between the positions of two poses.
inline double SquaredDistance(const Pose2& a, const Pose2& b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

std::string ToString(const Pose2& p);

}  // namespace slamtune
