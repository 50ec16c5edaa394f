// Back-end interface (docs/engine.md §7): optimise the node values of a PoseGraph with the
// first node fixed, minimising sum over edges of e^T Lambda e with the SPA residual of §7.2.
//
// Two implementations reproduce the two ROS packages: SpaSolver (slam_karto's
// SysSPA2d::doSPA(40), §7.3) and CeresSolver (slam_toolbox's default plugin, §7.4); MakeSolver
// (make_solver.h) picks one. Solvers hold only options, so one instance can be shared by copies
// of the engine state.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/pose_graph.h"

namespace slamtune::slam {

// What one solve did.
struct SolveSummary {
  std::string backend;  // "spa" or "ceres"
  int iterations = 0;   // LM iterations run (accepted and rejected)
  int accepted_steps = 0;
  double initial_cost = 0.0;  // sum e^T Lambda e before
  double final_cost = 0.0;    // and after
  bool updated = false;       // false when the solver left the node values unchanged
  bool usable = true;         // false: write nothing back (Ceres "solution unusable", §7.4)
  std::string termination;    // why it stopped
  double wall_s = 0.0;        // wall time of the solve (set by the caller that times it)
  // Per iteration that took a step (spa only): the cost after the step and whether it was kept.
  struct Step {
    double cost = 0.0;
    bool accepted = false;
  };
  std::vector<Step> steps;
  int cholesky_failures = 0;  // spa: factorisations that failed (the step was then the gradient)
};

// §7.2 error of one edge for node values a (source) and b (target):
// e_xy = R(a.theta)^T (b.xy - a.xy) - z.xy, e_theta = wrap(b.theta - a.theta - z.theta) (one +-2 pi wrap),
// computed as the SPA back-end computes it (spa_system.h: R^T b.xy + (-(R^T a.xy)) - z.xy).
Eigen::Vector3d EdgeError(const Pose2& a, const Pose2& b, const Pose2& z);

// sum over edges, in order, of e^T Lambda e (SPA arithmetic).
double GraphCost(std::span<const Pose2> nodes, std::span<const Edge> edges);

class PoseGraphSolver {
 public:
  virtual ~PoseGraphSolver() = default;
  virtual const char* name() const = 0;
  // Everything a solve's result depends on besides the graph: the back-end and its options, as
  // text (e.g. "ceres None SPARSE_NORMAL_CHOLESKY JACOBI LEVENBERG_MARQUARDT TRADITIONAL_DOGLEG").
  // Solves are shared between runs under it (sharing/solve_cache.h).
  virtual std::string Identity() const { return name(); }
  // Optimises `nodes` (index = vertex id) in place; node 0 is fixed. Deterministic.
  virtual SolveSummary Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const = 0;
};

// The back-ends: slam_karto's SPA (§7.3) and slam_toolbox's Ceres (§7.4).
enum class SolverKind { kSpa, kCeres };
// The options of slam_toolbox's Ceres back-end, as its CeresSolver::Configure
// (solvers/ceres_solver.cpp) reads them from ceres_loss_function, ceres_linear_solver,
// ceres_preconditioner, ceres_trust_strategy and ceres_dogleg_type. The first value of each enum
// is what the node uses for a text it does not know (slam/params/params_yaml.h reads them that way).
// The robust loss on every edge has scale 0.7.
enum class CeresLoss { kNone, kHuber, kCauchy };
enum class CeresLinearSolver { kSparseNormalCholesky, kSparseSchur, kIterativeSchur, kCgnr };
enum class CeresPreconditioner { kJacobi, kIdentity, kSchurJacobi };
enum class CeresTrustStrategy { kLevenbergMarquardt, kDogleg };
enum class CeresDoglegType { kTraditional, kSubspace };

// Their names in parameter files: "spa", "ceres"; "None", "HuberLoss", "CauchyLoss";
// "SPARSE_NORMAL_CHOLESKY", ...; "JACOBI", ...; "LEVENBERG_MARQUARDT", "DOGLEG";
// "TRADITIONAL_DOGLEG", "SUBSPACE_DOGLEG" (Ceres's own names, as the node's YAML has them).
const char* NameOf(SolverKind kind);
const char* NameOf(CeresLoss loss);
const char* NameOf(CeresLinearSolver solver);
const char* NameOf(CeresPreconditioner preconditioner);
const char* NameOf(CeresTrustStrategy strategy);
const char* NameOf(CeresDoglegType type);

// The Ceres back-end's choices together; the defaults are the node's for keys a file leaves out.
struct CeresChoices {
  CeresLoss loss = CeresLoss::kNone;
  CeresLinearSolver linear_solver = CeresLinearSolver::kSparseNormalCholesky;
  CeresPreconditioner preconditioner = CeresPreconditioner::kJacobi;
  CeresTrustStrategy trust_strategy = CeresTrustStrategy::kLevenbergMarquardt;
  CeresDoglegType dogleg_type = CeresDoglegType::kTraditional;  // used with kDogleg only

  friend bool operator==(const CeresChoices&, const CeresChoices&) = default;
};

}  // namespace slamtune::slam
