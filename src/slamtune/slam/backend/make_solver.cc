#include "slamtune/slam/backend/make_solver.h"

#include "slamtune/slam/backend/ceres_solver.h"
#include "slamtune/slam/backend/spa_solver.h"

namespace slamtune::slam {

std::shared_ptr<const PoseGraphSolver> MakeSolver(SolverKind kind, const CeresChoices& ceres) {
  if (kind == SolverKind::kSpa) return std::make_shared<const SpaSolver>();
  CeresOptions options;
  options.choices = ceres;
  return std::make_shared<const CeresSolver>(options);
}

}  // namespace slamtune::slam
