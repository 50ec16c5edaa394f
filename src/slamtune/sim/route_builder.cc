#include "slamtune/sim/route_builder.h"

#include "slamtune/common/error.h"

namespace slamtune::sim {

RouteBuilder& RouteBuilder::To(double x, double y) {
  waypoints_.emplace_back(x, y);
  return *this;
}

RouteBuilder& RouteBuilder::VisitRoom(const Eigen::Vector2d& door, const Eigen::Vector2d& inward,
                                      const Eigen::Vector2d& along, double corridor_offset, double loop_half_width,
                                      double loop_near, double loop_far) {
  SLAMTUNE_CHECK(std::abs(inward.dot(along)) < 1e-9);
  SLAMTUNE_CHECK(corridor_offset > 0.0 && loop_half_width > 0.0 && 0.0 < loop_near && loop_near < loop_far);
  // Local coordinates (u along the corridor, n into the room), origin at the doorway centre.
  const auto at = [&](double u, double n) -> Eigen::Vector2d { return door + u * along + n * inward; };
  const double w = loop_half_width;
  for (const Eigen::Vector2d& p : {at(0, -corridor_offset), at(0, loop_near), at(w, loop_near), at(w, loop_far),
                                   at(-w, loop_far), at(-w, loop_near), at(0, loop_near), at(0, -corridor_offset)}) {
    waypoints_.push_back(p);
  }
  return *this;
}

}  // namespace slamtune::sim
