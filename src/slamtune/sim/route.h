// The robot's path: straight legs through waypoints, with each corner rounded by a circular arc.
//
// A route is a chain of constant-curvature pieces (lines: curvature 0; arcs: +-1/radius), so
// the pose at any arc length s has a closed form and the robot's heading is continuous, as
// for a differential-drive robot that follows a planned path at constant speed. A corner
// whose neighbouring legs are too short for the requested radius gets the largest radius that
// fits (the arc ends at most halfway along each leg).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::sim {

// One constant-curvature piece: starts at `start`, runs `length` metres with `curvature` (1/m,
// positive = turning left).
struct RoutePiece {
  Pose2 start;
  double start_s = 0.0;  // arc length at the start of the piece (m)
  double length = 0.0;   // m
  double curvature = 0.0;
};

class Route {
 public:
  // `waypoints` (m, >= 2, consecutive ones distinct) are joined by straight legs; every corner
  // turns by less than 170 degrees and is rounded with radius <= `turn_radius` (m, > 0).
  // Built-in worlds only: broken routes are programming errors (SLAMTUNE_CHECK).
  Route(const std::vector<Eigen::Vector2d>& waypoints, double turn_radius);

  double length() const { return length_; }
  // Pose at arc length s (clamped into [0, length]); heading = direction of travel.
  Pose2 PoseAt(double s) const;
  // Curvature (1/m) at arc length s; the robot's turn rate is speed * curvature.
  double CurvatureAt(double s) const;
  const std::vector<RoutePiece>& pieces() const { return pieces_; }

 private:
  const RoutePiece& PieceAt(double s) const;
  void Append(double length, double curvature);

  std::vector<RoutePiece> pieces_;
  Pose2 end_;  // pose at the end of the last appended piece
  double length_ = 0.0;
};

// Pose after travelling `s` metres along a constant-curvature piece from `start`.
Pose2 AdvanceAlongArc(const Pose2& start, double curvature, double s);

}  // namespace slamtune::sim
