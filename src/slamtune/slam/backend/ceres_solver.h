// slam_toolbox's default back-end (solver_plugins::CeresSolver, docs/engine.md §7.4):
// Ceres 2.1 on the SPA residual whitened by the upper Cholesky factor of the information
// (r = U e, Lambda = U^T U); x, y and theta of each node are separate 1-D parameter blocks, theta
// with a wrap-around manifold; trust-region Levenberg-Marquardt with SPARSE_NORMAL_CHOLESKY and
// the toolbox's tolerances. An unusable solution leaves the nodes unchanged.
#pragma once

#include <string>

#include "slamtune/slam/backend/pose_graph_solver.h"

namespace slamtune::slam {

struct CeresOptions {
  CeresLoss loss = CeresLoss::kNone;  // scale 0.7
  int max_iterations = 50;     // Ceres default
  double function_tolerance = 1e-3;
  double gradient_tolerance = 1e-6;
  double parameter_tolerance = 1e-3;
  double min_relative_decrease = 1e-3;
  double initial_trust_region_radius = 1e4;
  double max_trust_region_radius = 1e8;
  double min_trust_region_radius = 1e-16;
  double min_lm_diagonal = 1e-6;
  double max_lm_diagonal = 1e32;
  int max_consecutive_nonmonotonic_steps = 3;
};

class CeresSolver final : public PoseGraphSolver {
 public:
  explicit CeresSolver(const CeresOptions& options = {});
  const char* name() const override { return "ceres"; }
  SolveSummary Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const override;

 private:
  CeresOptions options_;
};

}  // namespace slamtune::slam
