#include "slamtune/slam/backend/ceres_solver.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
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
  EXPECT_EQ(nodes[0], ring.truth[0]);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    EXPECT_NEAR(nodes[k].x, ring.truth[k].x, 1e-6) << k;
    EXPECT_NEAR(nodes[k].y, ring.truth[k].y, 1e-6) << k;
    EXPECT_NEAR(NormalizeAngle(nodes[k].theta - ring.truth[k].theta), 0.0, 1e-6) << k;
  }
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
  PoseGraph g = ring.graph;
  Pose2 biased = ring.truth[15];
  biased.y += 0.3;
  g.LinkScans(2, 15, ring.truth[2], biased, Eigen::Matrix3d::Identity() * 0.05, EdgeKind::kLoop);
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
    o.loss = loss;
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

}  // namespace
}  // namespace slamtune::slam
