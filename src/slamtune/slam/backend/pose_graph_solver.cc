#include "slamtune/slam/backend/pose_graph_solver.h"

#include <cmath>

#include "slamtune/common/error.h"
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

const char* NameOf(SolverKind kind) {
  switch (kind) {
    case SolverKind::kSpa: return "spa";
    case SolverKind::kCeres: return "ceres";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* NameOf(CeresLoss loss) {
  switch (loss) {
    case CeresLoss::kNone: return "None";
    case CeresLoss::kHuber: return "HuberLoss";
    case CeresLoss::kCauchy: return "CauchyLoss";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* NameOf(CeresLinearSolver solver) {
  switch (solver) {
    case CeresLinearSolver::kSparseNormalCholesky: return "SPARSE_NORMAL_CHOLESKY";
    case CeresLinearSolver::kSparseSchur: return "SPARSE_SCHUR";
    case CeresLinearSolver::kIterativeSchur: return "ITERATIVE_SCHUR";
    case CeresLinearSolver::kCgnr: return "CGNR";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* NameOf(CeresPreconditioner preconditioner) {
  switch (preconditioner) {
    case CeresPreconditioner::kJacobi: return "JACOBI";
    case CeresPreconditioner::kIdentity: return "IDENTITY";
    case CeresPreconditioner::kSchurJacobi: return "SCHUR_JACOBI";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* NameOf(CeresTrustStrategy strategy) {
  switch (strategy) {
    case CeresTrustStrategy::kLevenbergMarquardt: return "LEVENBERG_MARQUARDT";
    case CeresTrustStrategy::kDogleg: return "DOGLEG";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

const char* NameOf(CeresDoglegType type) {
  switch (type) {
    case CeresDoglegType::kTraditional: return "TRADITIONAL_DOGLEG";
    case CeresDoglegType::kSubspace: return "SUBSPACE_DOGLEG";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

}  // namespace slamtune::slam
