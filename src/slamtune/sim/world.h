// A simulated world: line-segment walls and the route the robot drives through them.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "slamtune/sim/odometry_fault.h"
#include "slamtune/sim/ray_caster.h"

namespace slamtune::sim {

struct World {
  std::string name;
  std::string description;  // one line, shown by `slamtune simulate --list`
  std::vector<Segment> walls;
  // The robot's route (m): straight legs between waypoints, corners rounded (see route.h).
  std::vector<Eigen::Vector2d> waypoints;
  double turn_radius = 0.5;  // m, largest radius of the arcs at the corners
  // Odometry failures planted in this world (odometry_fault.h), applied on top of the
  // simulation's own odometry options; none in the plain worlds.
  std::vector<OdometryFault> odometry_faults;
};

// Builds walls from simple shapes. Coordinates in metres.
class WallBuilder {
 public:
  // A gap or niche in a wall: centred `at` metres from the wall's start, `width` metres wide.
  // depth == 0: an open doorway. depth != 0: a closed recess that deep, to the left of the
  // wall's direction when positive (to the right when negative); it gives long walls features.
  struct Opening {
    double at = 0.0;
    double width = 1.0;
    double depth = 0.0;
  };

  void Wall(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
  // The wall from a to b with openings (sorted by `at`, non-overlapping, inside the wall).
  void WallWithOpenings(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::vector<Opening>& openings);
  // Closed axis-aligned rectangle (pillar, cabinet, desk, or a room outline without doors).
  void Box(const Eigen::Vector2d& min, const Eigen::Vector2d& max);

  std::vector<Segment> Take() { return std::move(walls_); }

 private:
  std::vector<Segment> walls_;
};

}  // namespace slamtune::sim
