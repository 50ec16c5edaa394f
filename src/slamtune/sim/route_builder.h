// Builds a world's waypoint list, with a helper for detours into rooms.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace slamtune::sim {

class RouteBuilder {
 public:
  explicit RouteBuilder(const Eigen::Vector2d& start) : waypoints_{start} {}

  RouteBuilder& To(double x, double y);

  // Detour through the doorway centred at `door` (on the room's wall): from the corridor
  // centreline `corridor_offset` metres outside the wall, straight in along `inward` (unit
  // normal into the room), once round a rectangle inside the room (`loop_half_width` metres
  // either side of the door axis, between `loop_near` and `loop_far` metres from the wall) and
  // out the same way, ready to continue along `along` (unit, the corridor's travel direction).
  // Every corner is a 90 degree turn, so the route rounds them smoothly.
  RouteBuilder& VisitRoom(const Eigen::Vector2d& door, const Eigen::Vector2d& inward, const Eigen::Vector2d& along,
                          double corridor_offset, double loop_half_width, double loop_near, double loop_far);

  std::vector<Eigen::Vector2d> Take() { return std::move(waypoints_); }

 private:
  std::vector<Eigen::Vector2d> waypoints_;
};

}  // namespace slamtune::sim
