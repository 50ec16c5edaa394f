#include "slamtune/slam/backend/ceres_solver.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <cmath>

#include "slamtune/common/karto_math.h"

namespace slamtune::slam {
namespace {

// Wraps into [-pi, pi) with whole turns; differentiable for Jets.
template <typename T>
T WrapAngle(const T& angle) {
  const T two_pi(2.0 * kPi);
  return angle - two_pi * ceres::floor((angle + T(kPi)) / two_pi);
}

// §7.2 residual whitened by U (Lambda = U^T U), on six 1-D blocks (x, y, theta of both nodes).
class EdgeResidual {
 public:
  EdgeResidual(const Pose2& z, const Eigen::Matrix3d& sqrt_information) : z_(z), sqrt_information_(sqrt_information) {}

  template <typename T>
  bool operator()(const T* xa, const T* ya, const T* ta, const T* xb, const T* yb, const T* tb, T* residual) const {
    const T c = ceres::cos(*ta), s = ceres::sin(*ta);
    const T dx = *xb - *xa, dy = *yb - *ya;
    Eigen::Matrix<T, 3, 1> e;
    e(0) = c * dx + s * dy - T(z_.x);
    e(1) = -s * dx + c * dy - T(z_.y);
    e(2) = WrapAngle((*tb - *ta) - T(z_.theta));
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = sqrt_information_.cast<T>() * e;
    return true;
  }

 private:
  Pose2 z_;
  Eigen::Matrix3d sqrt_information_;
};

// Heading manifold: x (+) delta = wrap(x + delta).
struct AngleManifoldFunctor {
  template <typename T>
  bool Plus(const T* x, const T* delta, T* out) const {
    *out = WrapAngle(*x + *delta);
    return true;
  }
  template <typename T>
  bool Minus(const T* y, const T* x, T* out) const {
    *out = WrapAngle(*y - *x);
    return true;
  }
};

ceres::LossFunction* MakeLoss(CeresLoss loss) {
  switch (loss) {
    case CeresLoss::kNone: return nullptr;
    case CeresLoss::kHuber: return new ceres::HuberLoss(0.7);
    case CeresLoss::kCauchy: return new ceres::CauchyLoss(0.7);
  }
  return nullptr;
}

ceres::LinearSolverType LinearSolverOf(CeresLinearSolver solver) {
  switch (solver) {
    case CeresLinearSolver::kSparseNormalCholesky: return ceres::SPARSE_NORMAL_CHOLESKY;
    case CeresLinearSolver::kSparseSchur: return ceres::SPARSE_SCHUR;
    case CeresLinearSolver::kIterativeSchur: return ceres::ITERATIVE_SCHUR;
    case CeresLinearSolver::kCgnr: return ceres::CGNR;
  }
  return ceres::SPARSE_NORMAL_CHOLESKY;
}

ceres::PreconditionerType PreconditionerOf(CeresPreconditioner preconditioner) {
  switch (preconditioner) {
    case CeresPreconditioner::kJacobi: return ceres::JACOBI;
    case CeresPreconditioner::kIdentity: return ceres::IDENTITY;
    case CeresPreconditioner::kSchurJacobi: return ceres::SCHUR_JACOBI;
  }
  return ceres::JACOBI;
}

// The solver options of slam_toolbox's CeresSolver::Configure for these choices.
ceres::Solver::Options SolverOptionsOf(const CeresOptions& options) {
  const CeresChoices& c = options.choices;
  ceres::Solver::Options o;
  o.linear_solver_type = LinearSolverOf(c.linear_solver);
  o.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  o.preconditioner_type = PreconditionerOf(c.preconditioner);
  o.trust_region_strategy_type =
      c.trust_strategy == CeresTrustStrategy::kDogleg ? ceres::DOGLEG : ceres::LEVENBERG_MARQUARDT;
  if (o.trust_region_strategy_type == ceres::DOGLEG) {
    o.dogleg_type = c.dogleg_type == CeresDoglegType::kSubspace ? ceres::SUBSPACE_DOGLEG : ceres::TRADITIONAL_DOGLEG;
  }
  o.dynamic_sparsity = o.linear_solver_type == ceres::SPARSE_NORMAL_CHOLESKY;
  o.max_num_iterations = options.max_iterations;
  o.function_tolerance = options.function_tolerance;
  o.gradient_tolerance = options.gradient_tolerance;
  o.parameter_tolerance = options.parameter_tolerance;
  o.min_relative_decrease = options.min_relative_decrease;
  o.use_nonmonotonic_steps = true;
  o.max_consecutive_nonmonotonic_steps = options.max_consecutive_nonmonotonic_steps;
  o.max_num_consecutive_invalid_steps = options.max_consecutive_invalid_steps;
  o.jacobi_scaling = true;
  o.initial_trust_region_radius = options.initial_trust_region_radius;
  o.max_trust_region_radius = options.max_trust_region_radius;
  o.min_trust_region_radius = options.min_trust_region_radius;
  o.min_lm_diagonal = options.min_lm_diagonal;
  o.max_lm_diagonal = options.max_lm_diagonal;
  // The node runs 50 threads; the solvers' results do not depend on it, and the tuner runs
  // one SLAM run per core.
  o.num_threads = 1;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  return o;
}

}  // namespace

std::string CeresChoicesProblem(const CeresChoices& choices) {
  CeresOptions options;
  options.choices = choices;
  std::string why;
  return SolverOptionsOf(options).IsValid(&why) ? "" : why;
}

std::string CeresSolver::Identity() const {
  const CeresChoices& c = options_.choices;
  return fmt::format("ceres {} {} {} {} {}", NameOf(c.loss), NameOf(c.linear_solver), NameOf(c.preconditioner),
                     NameOf(c.trust_strategy), NameOf(c.dogleg_type));
}

CeresSolver::CeresSolver(const CeresOptions& options) : options_(options) {}

SolveSummary CeresSolver::Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const {
  SolveSummary summary;
  summary.backend = "ceres";
  summary.initial_cost = summary.final_cost = GraphCost(nodes, edges);
  if (nodes.size() < 2 || edges.empty()) {
    summary.termination = "nothing to optimise";
    return summary;
  }
  // Parameter storage: x, y, theta of node k at 3k, 3k + 1, 3k + 2 (stable addresses).
  std::vector<double> values(3 * nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    values[3 * k] = nodes[k].x;
    values[3 * k + 1] = nodes[k].y;
    values[3 * k + 2] = nodes[k].theta;
  }
  ceres::Problem problem;
  auto* manifold = new ceres::AutoDiffManifold<AngleManifoldFunctor, 1, 1>;
  bool manifold_owned = false;
  for (const Edge& e : edges) {
    const Eigen::Matrix3d u = e.constraint.information.llt().matrixU();
    auto* cost = new ceres::AutoDiffCostFunction<EdgeResidual, 3, 1, 1, 1, 1, 1, 1>(
        new EdgeResidual(e.constraint.measurement, u));
    double* a = &values[3 * e.source];
    double* b = &values[3 * e.target];
    problem.AddResidualBlock(cost, MakeLoss(options_.choices.loss), a, a + 1, a + 2, b, b + 1, b + 2);
  }
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    double* theta = &values[3 * k + 2];
    if (problem.HasParameterBlock(theta)) {
      problem.SetManifold(theta, manifold);
      manifold_owned = true;
    }
  }
  if (!manifold_owned) delete manifold;
  for (int k = 0; k < 3; ++k) {  // first node fixed (gauge)
    if (problem.HasParameterBlock(&values[k])) problem.SetParameterBlockConstant(&values[k]);
  }

  const ceres::Solver::Options o = SolverOptionsOf(options_);
  ceres::Solver::Summary s;
  ceres::Solve(o, &problem, &s);

  summary.iterations = static_cast<int>(s.iterations.size());
  summary.accepted_steps = s.num_successful_steps;
  summary.termination = s.message;
  if (!s.IsSolutionUsable()) {  // §7.4: corrections not updated, poses unchanged
    summary.usable = false;
    return summary;
  }
  for (std::size_t k = 1; k < nodes.size(); ++k) {
    nodes[k] = {values[3 * k], values[3 * k + 1], values[3 * k + 2]};
  }
  summary.updated = true;
  summary.final_cost = GraphCost(nodes, edges);
  return summary;
}

}  // namespace slamtune::slam
