#include "slamtune/slam/backend/pose_graph_solver.h"

#include <fmt/format.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/slam/backend/ceres_solver.h"
#include "slamtune/slam/backend/spa_solver.h"
#include "slamtune/slam/backend/spa_system.h"

namespace slamtune::slam {

// §7.2, with the SPA system's arithmetic.
Eigen::Vector3d EdgeError(const Pose2& a, const Pose2& b, const Pose2& z) {
  return SpaEdgeError(MakeSpaNodeFrame(a), MakeSpaNodeFrame(b), z);
}

double GraphCost(std::span<const Pose2> nodes, std::span<const Edge> edges) {
  std::vector<SpaNodeFrame> frames;
  frames.reserve(nodes.size());
  for (const Pose2& n : nodes) frames.push_back(MakeSpaNodeFrame(n));
  return SpaGraphCost(frames, edges);
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
