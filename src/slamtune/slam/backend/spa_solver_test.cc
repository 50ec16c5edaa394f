#include "slamtune/slam/backend/spa_solver.h"

#include <gtest/gtest.h>

#include <cmath>

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
  testing::ExpectRecoversRing(nodes, ring, 1e-6);
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
  // A second, biased loop measurement 1 -> 11 (x off by 0.5 m).
  const PoseGraph g = testing::WithBiasedLoop(ring, 1, 11, {0.5, 0.0}, 0.02);
  std::vector<Pose2> nodes = g.node_values();
  const SolveSummary s = SpaSolver().Solve(nodes, g.edges());
  EXPECT_TRUE(s.updated);
  EXPECT_LT(s.final_cost, s.initial_cost);
  EXPECT_EQ(nodes[0], ring.truth[0]);
  EXPECT_GT(std::fabs(nodes[11].x - ring.truth[11].x), 1e-3);
}

// A ring of n poses with deterministic perturbations (no random numbers, so the pinned values
// below depend only on the arithmetic) and a loop edge that disagrees with the ring by 0.3 m.
PoseGraph PerturbedRing(int n) {
  std::vector<Pose2> truth;
  for (int k = 0; k < n; ++k) {
    const double a = kTwoPi * k / n;
    truth.push_back({4.0 * std::cos(a), 4.0 * std::sin(a), NormalizeAngle(a + kPi / 2)});
  }
  PoseGraph g;
  for (int k = 0; k < n; ++k) {
    Pose2 p = truth[k];
    if (k > 0) {
      p.x += 0.2 * std::sin(1.7 * k);
      p.y += 0.2 * std::cos(2.3 * k);
      p.theta = NormalizeAngle(p.theta + 0.05 * std::sin(0.9 * k));
    }
    g.AddVertex(p);
  }
  Eigen::Matrix3d cov;
  cov << 0.02, 0.005, 0.001, 0.005, 0.04, 0.0, 0.001, 0.0, 0.01;
  for (int k = 0; k + 1 < n; ++k) g.LinkScans(k, k + 1, truth[k], truth[k + 1], cov, EdgeKind::kSequential);
  Pose2 biased = truth[n - 1];
  biased.x += 0.3;
  g.LinkScans(0, n - 1, truth[0], biased, cov, EdgeKind::kLoop);
  g.LinkScans(n / 2, 1, truth[n / 2], truth[1], cov * 4.0, EdgeKind::kLoop);  // block below the diagonal
  return g;
}

// The figures of a solve's summary that the pinned tests below fix exactly.
struct PinnedSummary {
  int iterations;
  int accepted_steps;
  double initial_cost;
  double final_cost;
};

// A solve's outcome: the node values it wrote and its summary.
struct RingSolve {
  std::vector<Pose2> nodes;
  SolveSummary summary;
};

// Solves PerturbedRing(n) with SPA and expects the summary's figures to be exactly `expected`;
// returns the solved nodes and the summary for the test's further checks.
RingSolve SolvePerturbedRingPinned(int n, const PinnedSummary& expected) {
  const PoseGraph g = PerturbedRing(n);
  RingSolve solve{g.node_values(), {}};
  solve.summary = SpaSolver().Solve(solve.nodes, g.edges());
  const SolveSummary& s = solve.summary;
  EXPECT_EQ(s.iterations, expected.iterations);
  EXPECT_EQ(s.accepted_steps, expected.accepted_steps);
  EXPECT_EQ(s.initial_cost, expected.initial_cost);
  EXPECT_EQ(s.final_cost, expected.final_cost);
  return solve;
}

// The solve is pinned bit for bit: these values are what the SPA arithmetic (spa_system.h,
// CSparse Cholesky with natural ordering below 101 rows, AMD above) produces, the arithmetic
// that reproduces slam_karto's loop closures on mit-killian. A change in any operation order
// shows up here.
TEST(SpaSolver, SmallRingSolveIsPinnedBitForBit) {
  // 21 rows: natural ordering.
  const std::vector<Pose2> nodes =
      SolvePerturbedRingPinned(8, {5, 4, 0x1.1d0c68ee4797fp+5, 0x1.302f512b6731dp-3}).nodes;
  const std::vector<Pose2> expected{
      {0x1p+2, 0x0p+0, 0x1.921fb54442d18p+0},
      {0x1.6b95b762977b4p+1, 0x1.6aae39b370a11p+1, 0x1.3013744bdfbc3p+1},
      {-0x1.7723ce16ed14dp-8, 0x1.f8e0dee8c39b2p+1, -0x1.8e024b5c57069p+1},
      {-0x1.654a027e24b88p+1, 0x1.56a2bc64496b6p+1, -0x1.28bd7f8c6247ep+1},
      {-0x1.ed09c516e271ap+1, -0x1.98e5b20e1b396p-3, -0x1.88d2e2d676fa6p+0},
      {-0x1.48d49d3b4e9acp+1, -0x1.7d506fbd520bdp+1, -0x1.82837978ef588p-1},
      {0x1.35c202307326ap-2, -0x1.03c8e650edb12p+2, 0x1.1e8d6a76705d8p-6},
      {0x1.8f40b53d25eb8p+1, -0x1.6aae39b350fc6p+1, 0x1.9699fc5941ccdp-1},
  };
  ASSERT_EQ(nodes.size(), expected.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) EXPECT_EQ(nodes[k], expected[k]) << k;
}

TEST(SpaSolver, LargeRingSolveIsPinnedBitForBit) {
  // 117 rows: AMD ordering.
  const auto [nodes, s] = SolvePerturbedRingPinned(40, {8, 6, 0x1.5471615c6b26fp+7, 0x1.5bf1e7d1a60eep-4});
  EXPECT_EQ(nodes[1], (Pose2{0x1.fa86c56b515afp+1, 0x1.41bdb7fab016p-1, 0x1.bc1b05a233a3fp+0}));
  EXPECT_EQ(nodes[20], (Pose2{-0x1.f9852b2370b27p+1, -0x1.669a84c906bcfp-3, -0x1.8be73ae4feec5p+0}));
  EXPECT_EQ(nodes[39], (Pose2{0x1.0fa814ae9c06ap+2, -0x1.41bdb7faa3a8p-1, 0x1.69139a194f4b4p+0}));
  // One entry per step taken; the last kept step has the final cost.
  ASSERT_FALSE(s.steps.empty());
  double last_kept = s.initial_cost;
  for (const SolveSummary::Step& step : s.steps) {
    if (step.accepted) last_kept = step.cost;
  }
  EXPECT_EQ(last_kept, s.final_cost);
}

}  // namespace
}  // namespace slamtune::slam
