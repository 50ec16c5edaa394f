// The choice of back-end: the PoseGraphSolver (pose_graph_solver.h) a SolverKind names,
// slam_karto's SPA (spa_solver.h) or slam_toolbox's Ceres (ceres_solver.h). Kept apart from the
// interface, which then depends on neither implementation.
#pragma once

#include <memory>

#include "slamtune/slam/backend/pose_graph_solver.h"

namespace slamtune::slam {

// The back-end of `kind`; `ceres` applies to kCeres.
std::shared_ptr<const PoseGraphSolver> MakeSolver(SolverKind kind, const CeresChoices& ceres = {});

}  // namespace slamtune::slam
