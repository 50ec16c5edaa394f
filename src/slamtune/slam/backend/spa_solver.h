// slam_karto's back-end: sparse Levenberg-Marquardt of Konolige et al. 2010 ("Efficient sparse
// pose adjustment for 2D mapping", IROS), with the schedule of SysSPA2d::doSPA(40)
// (docs/engine.md §7.3): lambda = 1e-4 and an increase factor of 2 at every call; H = sum
// J^T Lambda J over free nodes with its diagonal scaled by (1 + lambda); solve by CSparse's
// sparse Cholesky; stop when |delta|^2 < (1e-8)^2 (delta not applied); on a cost decrease
// accept and halve lambda, else restore, multiply lambda by the factor and double the factor;
// at most 40 iterations; angles wrapped once after a step.
//
// The arithmetic (residual, Jacobians, block assembly, matrix layout, ordering) is sba's, in
// its order of operations (spa_system.h, sparse_cholesky.h), so that solves give the same bits
// as slam_karto's and the later decisions of the front end are the same.
#pragma once

#include "slamtune/slam/backend/pose_graph_solver.h"

namespace slamtune::slam {

struct SpaOptions {
  int max_iterations = 40;                // doSPA(40)
  double initial_lambda = 1e-4;           // reset at every call
  double min_squared_step = 1e-8 * 1e-8;  // stop when |delta|^2 is below this (sba's product, not 1e-16)
};

class SpaSolver final : public PoseGraphSolver {
 public:
  explicit SpaSolver(const SpaOptions& options = {}) : options_(options) {}
  const char* name() const override { return "spa"; }
  SolveSummary Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const override;

 private:
  SpaOptions options_;
};

}  // namespace slamtune::slam
