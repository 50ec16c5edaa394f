// slam_toolbox's default back-end (solver_plugins::CeresSolver, docs/engine.md §7.4):
// Ceres 2.1 on the SPA residual whitened by the upper Cholesky factor of the information
// (r = U e, Lambda = U^T U); x, y and theta of each node are separate 1-D parameter blocks, theta
// with a wrap-around manifold; the toolbox's tolerances and limits, and the linear solver,
// preconditioner, trust-region strategy and dogleg type its CeresSolver::Configure sets from its
// parameters (CeresChoices: Levenberg-Marquardt with SPARSE_NORMAL_CHOLESKY by default; dynamic
// sparsity with that solver only; a combination Ceres refuses, e.g. CGNR with SCHUR_JACOBI, fails
// every solve, as on the robot). An unusable solution leaves the nodes unchanged.
#pragma once

#include <string>

#include "slamtune/slam/backend/pose_graph_solver.h"

namespace slamtune::slam {

struct CeresOptions {
  CeresChoices choices;     // loss, linear solver, preconditioner, trust region
  int max_iterations = 50;  // Ceres default
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
  int max_consecutive_invalid_steps = 3;
};

// Why Ceres refuses the solver options of `choices` (Solver::Options::IsValid, e.g. DOGLEG with
// an iterative linear solver), or "" when it takes them. A node configured so never corrects a
// pose: every solve fails.
std::string CeresChoicesProblem(const CeresChoices& choices);

class CeresSolver final : public PoseGraphSolver {
 public:
  explicit CeresSolver(const CeresOptions& options = {});
  const char* name() const override { return "ceres"; }
  std::string Identity() const override;
  SolveSummary Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const override;

 private:
  CeresOptions options_;
};

}  // namespace slamtune::slam
