#include "slamtune/sim/route.h"

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

constexpr double kMaxTurn = 170.0 * kPi / 180.0;

double Heading(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

}  // namespace

Pose2 AdvanceAlongArc(const Pose2& start, double curvature, double s) {
  if (curvature == 0.0) {
    return {start.x + s * std::cos(start.theta), start.y + s * std::sin(start.theta), start.theta};
  }
  // Circle of radius 1/k: x' = x + (sin(th + k s) - sin th)/k, y' = y - (cos(th + k s) - cos th)/k.
  const double theta = start.theta + curvature * s;
  return {start.x + (std::sin(theta) - std::sin(start.theta)) / curvature,
          start.y - (std::cos(theta) - std::cos(start.theta)) / curvature, NormalizeAngle(theta)};
}

Route::Route(const std::vector<Eigen::Vector2d>& waypoints, double turn_radius) {
  SLAMTUNE_CHECK_MSG(waypoints.size() >= 2, "a route needs two waypoints");
  SLAMTUNE_CHECK(turn_radius > 0.0);
  const std::size_t n = waypoints.size();
  std::vector<double> leg_length(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    leg_length[i] = (waypoints[i + 1] - waypoints[i]).norm();
    SLAMTUNE_CHECK_MSG(leg_length[i] > 1e-9, "consecutive waypoints coincide");
  }
  // Signed turn and tangent length (distance from the waypoint to where its arc starts/ends).
  std::vector<double> turn(n, 0.0), tangent(n, 0.0), radius(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    turn[i] = NormalizeAngle(Heading(waypoints[i + 1] - waypoints[i]) - Heading(waypoints[i] - waypoints[i - 1]));
    SLAMTUNE_CHECK_MSG(std::fabs(turn[i]) < kMaxTurn, "route corner turns by 170 degrees or more");
    const double half_tan = std::tan(std::fabs(turn[i]) / 2.0);
    const double room = std::min(leg_length[i - 1], leg_length[i]) / 2.0;
    radius[i] = half_tan > 0.0 ? std::min(turn_radius, room / half_tan) : 0.0;
    tangent[i] = radius[i] * half_tan;
  }

  end_ = Pose2{waypoints[0].x(), waypoints[0].y(), Heading(waypoints[1] - waypoints[0])};
  for (std::size_t i = 0; i + 1 < n; ++i) {
    Append(leg_length[i] - tangent[i] - tangent[i + 1], 0.0);
    if (i + 2 < n && radius[i + 1] > 0.0) {
      const double sign = turn[i + 1] > 0.0 ? 1.0 : -1.0;
      Append(radius[i + 1] * std::fabs(turn[i + 1]), sign / radius[i + 1]);
    }
  }
  SLAMTUNE_CHECK(!pieces_.empty());
}

void Route::Append(double length, double curvature) {
  if (length <= 0.0) return;  // a leg fully used by its two arcs
  pieces_.push_back(RoutePiece{end_, length_, length, curvature});
  end_ = AdvanceAlongArc(end_, curvature, length);
  length_ += length;
}

const RoutePiece& Route::PieceAt(double s) const {
  // Last piece starting at or before s.
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                             [](double value, const RoutePiece& piece) { return value < piece.start_s; });
  return it == pieces_.begin() ? pieces_.front() : *std::prev(it);
}

Pose2 Route::PoseAt(double s) const {
  s = std::clamp(s, 0.0, length_);
  const RoutePiece& piece = PieceAt(s);
  return AdvanceAlongArc(piece.start, piece.curvature, std::min(s - piece.start_s, piece.length));
}

double Route::CurvatureAt(double s) const { return PieceAt(std::clamp(s, 0.0, length_)).curvature; }

}  // namespace slamtune::sim
