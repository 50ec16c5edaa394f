#include "slamtune/slam/backend/ceres_solver.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/slam/backend/make_solver.h"
#include "slamtune/slam/backend/spa_solver.h"
#include "slamtune/slam/testing/ring_graph.h"

namespace slamtune::slam {
namespace {

TEST(CeresSolver, RecoversANoisyRingWithTightTolerances) {
  auto ring = testing::MakeRingGraph(24, 5.0, 0.3, 0.1, 7);
  CeresOptions tight;
  tight.function_tolerance = tight.parameter_tolerance = tight.gradient_tolerance = 1e-14;
  std::vector<Pose2> nodes = ring.graph.node_values();
  const SolveSummary s = CeresSolver(tight).Solve(nodes, ring.graph.edges());
  EXPECT_TRUE(s.updated) << s.termination;
  EXPECT_LT(s.final_cost, 1e-12);
  testing::ExpectRecoversRing(nodes, ring, 1e-6);
}

// slam_toolbox's loose tolerances (function_tolerance 1e-3, §7.4) stop earlier than SPA.
TEST(CeresSolver, ToolboxTolerancesStopNearTheOptimum) {
  auto ring = testing::MakeRingGraph(24, 5.0, 0.3, 0.1, 7);
  std::vector<Pose2> nodes = ring.graph.node_values();
  const SolveSummary s = CeresSolver().Solve(nodes, ring.graph.edges());
  EXPECT_TRUE(s.updated) << s.termination;
  EXPECT_LT(s.final_cost, 1e-3 * s.initial_cost);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    EXPECT_NEAR(nodes[k].x, ring.truth[k].x, 1e-2) << k;
    EXPECT_NEAR(nodes[k].y, ring.truth[k].y, 1e-2) << k;
  }
}

TEST(CeresSolver, AgreesWithSpaOnAnInconsistentGraph) {
  auto ring = testing::MakeRingGraph(16, 3.0, 0.1, 0.05, 3);
  const PoseGraph g = testing::WithBiasedLoop(ring, 2, 15, {0.0, 0.3}, 0.05);
  std::vector<Pose2> spa = g.node_values(), ceres = spa;
  SpaSolver().Solve(spa, g.edges());
  const SolveSummary s = CeresSolver().Solve(ceres, g.edges());
  EXPECT_TRUE(s.updated);
  for (std::size_t k = 0; k < spa.size(); ++k) {
    EXPECT_NEAR(spa[k].x, ceres[k].x, 1e-3) << k;
    EXPECT_NEAR(spa[k].y, ceres[k].y, 1e-3) << k;
  }
}

TEST(CeresSolver, RobustLossesAndNames) {
  auto ring = testing::MakeRingGraph(10, 2.0, 0.05, 0.02, 5);
  for (CeresLoss loss : {CeresLoss::kHuber, CeresLoss::kCauchy}) {
    CeresOptions o;
    o.choices.loss = loss;
    std::vector<Pose2> nodes = ring.graph.node_values();
    const SolveSummary s = CeresSolver(o).Solve(nodes, ring.graph.edges());
    EXPECT_LT(s.final_cost, s.initial_cost) << NameOf(loss);
  }
  EXPECT_STREQ(NameOf(CeresLoss::kNone), "None");
  EXPECT_STREQ(NameOf(CeresLoss::kHuber), "HuberLoss");
  EXPECT_STREQ(NameOf(CeresLoss::kCauchy), "CauchyLoss");
  EXPECT_STREQ(MakeSolver(SolverKind::kCeres)->name(), "ceres");
  EXPECT_STREQ(MakeSolver(SolverKind::kSpa)->name(), "spa");
}

// Every linear solver, preconditioner and trust-region strategy slam_toolbox offers reaches a
// usable solution of a ring; the combination Ceres refuses leaves the nodes as they were, as
// the node's solve then does.
TEST(CeresSolver, HonoursEveryChoiceOfTheNode) {
  auto ring = testing::MakeRingGraph(12, 2.0, 0.05, 0.02, 7);
  std::vector<Pose2> reference = ring.graph.node_values();
  CeresSolver().Solve(reference, ring.graph.edges());
  std::vector<CeresChoices> usable;
  for (CeresLinearSolver solver : {CeresLinearSolver::kSparseNormalCholesky, CeresLinearSolver::kSparseSchur,
                                   CeresLinearSolver::kIterativeSchur, CeresLinearSolver::kCgnr}) {
    for (CeresTrustStrategy trust : {CeresTrustStrategy::kLevenbergMarquardt, CeresTrustStrategy::kDogleg}) {
      CeresChoices c;
      c.linear_solver = solver;
      c.trust_strategy = trust;
      const bool iterative = solver == CeresLinearSolver::kIterativeSchur || solver == CeresLinearSolver::kCgnr;
      if (trust == CeresTrustStrategy::kDogleg && iterative) continue;  // refused below
      EXPECT_EQ(CeresChoicesProblem(c), "");
      usable.push_back(c);
    }
  }
  CeresChoices subspace;
  subspace.trust_strategy = CeresTrustStrategy::kDogleg;
  subspace.dogleg_type = CeresDoglegType::kSubspace;
  usable.push_back(subspace);
  CeresChoices schur_jacobi;
  schur_jacobi.linear_solver = CeresLinearSolver::kIterativeSchur;
  schur_jacobi.preconditioner = CeresPreconditioner::kSchurJacobi;
  usable.push_back(schur_jacobi);
  for (const CeresChoices& c : usable) {
    std::vector<Pose2> nodes = ring.graph.node_values();
    const SolveSummary s = CeresSolver({.choices = c}).Solve(nodes, ring.graph.edges());
    const std::string name = MakeSolver(SolverKind::kCeres, c)->Identity();
    ASSERT_TRUE(s.usable) << name << ": " << s.termination;
    EXPECT_LT(s.final_cost, s.initial_cost) << name;
    for (std::size_t k = 0; k < nodes.size(); ++k) EXPECT_NEAR(nodes[k].x, reference[k].x, 1e-2) << name << " " << k;
  }
  // DOGLEG is not Levenberg-Marquardt: on the same graph the iterations differ.
  std::vector<Pose2> lm = ring.graph.node_values(), dogleg = lm;
  const SolveSummary s_lm = CeresSolver().Solve(lm, ring.graph.edges());
  CeresChoices d;
  d.trust_strategy = CeresTrustStrategy::kDogleg;
  const SolveSummary s_dogleg = CeresSolver({.choices = d}).Solve(dogleg, ring.graph.edges());
  EXPECT_TRUE(s_lm.final_cost != s_dogleg.final_cost || lm[5].x != dogleg[5].x);
  // Combinations Ceres refuses (DOGLEG with an iterative solver): every solve fails and nothing
  // moves, as on the robot; CeresChoicesProblem says why beforehand. (CGNR with SCHUR_JACOBI
  // aborts Ceres 2.1 itself: MapperParams::Validate refuses it.)
  CeresChoices dogleg_iterative;
  dogleg_iterative.linear_solver = CeresLinearSolver::kIterativeSchur;
  dogleg_iterative.trust_strategy = CeresTrustStrategy::kDogleg;
  CeresChoices dogleg_cgnr = dogleg_iterative;
  dogleg_cgnr.linear_solver = CeresLinearSolver::kCgnr;
  for (const CeresChoices& refused : {dogleg_iterative, dogleg_cgnr}) {
    EXPECT_NE(CeresChoicesProblem(refused), "");
    std::vector<Pose2> nodes = ring.graph.node_values();
    const SolveSummary s = CeresSolver({.choices = refused}).Solve(nodes, ring.graph.edges());
    EXPECT_FALSE(s.usable);
    EXPECT_EQ(nodes, ring.graph.node_values());
  }
}

}  // namespace
}  // namespace slamtune::slam
