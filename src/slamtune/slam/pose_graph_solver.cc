#include "slamtune/slam/pose_graph_solver.h"

#include <fmt/format.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/slam/ceres_solver.h"
#include "slamtune/slam/spa_solver.h"

namespace slamtune::slam {

// §7.2.
Eigen::Vector3d EdgeError(const Pose2& a, const Pose2& b, const Pose2& z) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double dx = b.x - a.x, dy = b.y - a.y;
  double et = b.theta - a.theta - z.theta;
  if (et > kPi) {
    et -= kTwoPi;
  } else if (et < -kPi) {
    et += kTwoPi;
  }
  return {c * dx + s * dy - z.x, -s * dx + c * dy - z.y, et};
}

double GraphCost(std::span<const Pose2> nodes, std::span<const Edge> edges) {
  double cost = 0.0;
  for (const Edge& e : edges) {
    const Eigen::Vector3d err = EdgeError(nodes[e.source], nodes[e.target], e.constraint.measurement);
    cost += err.dot(e.constraint.information * err);
  }
  return cost;
}

std::shared_ptr<const PoseGraphSolver> MakeSolver(const std::string& name, const std::string& ceres_loss) {
  if (name == "spa") return std::make_shared<const SpaSolver>();
  if (name == "ceres") {
    CeresOptions options;
    options.loss = ceres_loss;
    return std::make_shared<const CeresSolver>(options);
  }
  throw InputError(fmt::format("solver '{}' is not supported: must be spa or ceres", name));
}

}  // namespace slamtune::slam
