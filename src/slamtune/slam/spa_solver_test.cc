#include "slamtune/slam/spa_solver.h"

#include <gtest/gtest.h>

#include "slamtune/slam/testing/ring_graph.h"

namespace slamtune::slam {
namespace {

TEST(EdgeError, ResidualOfSection72) {
  const Pose2 a{1, 1, kPi / 2}, b{1, 3, kPi / 2};
  const Eigen::Vector3d e = EdgeError(a, b, {2, 0, 0});
  EXPECT_NEAR(e.norm(), 0.0, 1e-12);
  // Heading error wraps once: 3.1 - (-3.1) - 0 = 6.2 -> 6.2 - 2 pi.
  EXPECT_NEAR(EdgeError({0, 0, -3.1}, {0, 0, 3.1}, {0, 0, 0})(2), 6.2 - kTwoPi, 1e-12);
}

TEST(SpaSolver, RecoversANoisyRingWithALoopEdge) {
  auto ring = testing::MakeRingGraph(24, 5.0, 0.3, 0.1, 7);
  std::vector<Pose2> nodes = ring.graph.node_values();
  const SolveSummary s = SpaSolver().Solve(nodes, ring.graph.edges());
  EXPECT_TRUE(s.updated);
  EXPECT_GT(s.initial_cost, 1.0);
  EXPECT_LT(s.final_cost, 1e-12);
  EXPECT_LE(s.iterations, 40);
  EXPECT_EQ(nodes[0], ring.truth[0]);  // fixed
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    EXPECT_NEAR(nodes[k].x, ring.truth[k].x, 1e-6) << k;
    EXPECT_NEAR(nodes[k].y, ring.truth[k].y, 1e-6) << k;
    EXPECT_NEAR(NormalizeAngle(nodes[k].theta - ring.truth[k].theta), 0.0, 1e-6) << k;
  }
}

TEST(SpaSolver, IsDeterministicAndStopsOnSmallSteps) {
  auto ring = testing::MakeRingGraph(30, 4.0, 0.2, 0.05, 11);
  std::vector<Pose2> a = ring.graph.node_values(), b = a;
  const SolveSummary sa = SpaSolver().Solve(a, ring.graph.edges());
  SpaSolver().Solve(b, ring.graph.edges());
  EXPECT_EQ(a, b);
  EXPECT_EQ(sa.termination, "step below tolerance");
  // A second solve from the optimum stops at once without moving anything.
  const std::vector<Pose2> before = a;
  const SolveSummary again = SpaSolver().Solve(a, ring.graph.edges());
  EXPECT_EQ(again.iterations, 1);
  EXPECT_FALSE(again.updated);
  EXPECT_EQ(a, before);
}

TEST(SpaSolver, InconsistentLoopSpreadsTheErrorAndKeepsNodeZero) {
  auto ring = testing::MakeRingGraph(12, 3.0, 0.0, 0.0, 1);
  PoseGraph g = ring.graph;
  // A second, biased loop measurement 1 -> 11 (x off by 0.5 m).
  Pose2 biased = ring.truth[11];
  biased.x += 0.5;
  g.LinkScans(1, 11, ring.truth[1], biased, Eigen::Matrix3d::Identity() * 0.02, EdgeKind::kLoop);
  std::vector<Pose2> nodes = g.node_values();
  const SolveSummary s = SpaSolver().Solve(nodes, g.edges());
  EXPECT_TRUE(s.updated);
  EXPECT_LT(s.final_cost, s.initial_cost);
  EXPECT_EQ(nodes[0], ring.truth[0]);
  EXPECT_GT(std::fabs(nodes[11].x - ring.truth[11].x), 1e-3);
}

}  // namespace
}  // namespace slamtune::slam
