#include "slamtune/slam/sharing/solve_cache.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <set>
#include <vector>

#include "slamtune/common/testing/same_bits.h"
#include "slamtune/slam/backend/make_solver.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::SameBits;

// A square loop of four poses with drifted initial values: the solve moves them.
struct Graph {
  std::vector<Pose2> nodes{{0, 0, 0}, {1.1, 0.05, 1.6}, {1.0, 1.2, 3.1}, {-0.1, 0.9, -1.5}};
  std::vector<Edge> edges;
  Graph() {
    const Pose2 truth[4] = {{0, 0, 0}, {1, 0, M_PI / 2}, {1, 1, M_PI}, {0, 1, -M_PI / 2}};
    for (int k = 0; k < 4; ++k) {
      const int a = k, b = (k + 1) % 4;
      Edge e;
      e.source = std::min(a, b);
      e.target = std::max(a, b);
      e.constraint = MakeConstraint(truth[e.source], truth[e.target], Eigen::Matrix3d::Identity() * 0.01);
      edges.push_back(e);
    }
  }
};

TEST(SolveCache, HitGivesTheSolversResultBitForBit) {
  const auto solver = MakeSolver(SolverKind::kSpa);
  Graph g;
  std::vector<Pose2> direct = g.nodes;
  const SolveSummary expected = solver->Solve(direct, g.edges);
  ASSERT_TRUE(expected.updated);

  SolveCache cache;
  const auto key = SolveCache::KeyOf("spa", g.nodes, g.edges);
  EXPECT_FALSE(cache.Find(key).has_value());
  std::vector<Pose2> first = g.nodes;
  const SolveSummary summary = solver->Solve(first, g.edges);
  cache.Store(key, {summary, first, {{0.5, 0.25, 0.0}}});
  const auto again = cache.Find(key);
  ASSERT_TRUE(again.has_value());
  EXPECT_TRUE(SameBits(again->nodes, direct));
  EXPECT_EQ(again->summary.iterations, expected.iterations);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(again->summary.final_cost), std::bit_cast<std::uint64_t>(expected.final_cost));
  ASSERT_EQ(again->barycenters.size(), 1u);
  EXPECT_EQ(again->barycenters[0].x, 0.5);
  EXPECT_EQ(cache.counters().hits, 1u);
  EXPECT_EQ(cache.counters().misses, 1u);
}

TEST(SolveCache, KeyNamesBackendNodesAndEveryEdgeField) {
  Graph g;
  const std::string spa = MakeSolver(SolverKind::kSpa)->Identity();
  const auto key = SolveCache::KeyOf(spa, g.nodes, g.edges);
  EXPECT_NE(key, SolveCache::KeyOf(MakeSolver(SolverKind::kCeres)->Identity(), g.nodes, g.edges));
  EXPECT_NE(key, SolveCache::KeyOf(MakeSolver(SolverKind::kCeres, {.loss = CeresLoss::kHuber})->Identity(), g.nodes,
                                   g.edges));
  // Every option of the Ceres back-end is part of its identity.
  const CeresChoices lm;
  CeresChoices dogleg;
  dogleg.trust_strategy = CeresTrustStrategy::kDogleg;
  CeresChoices subspace = dogleg;
  subspace.dogleg_type = CeresDoglegType::kSubspace;
  CeresChoices cgnr;
  cgnr.linear_solver = CeresLinearSolver::kCgnr;
  CeresChoices identity;
  identity.preconditioner = CeresPreconditioner::kIdentity;
  std::set<std::string> identities;
  for (const CeresChoices& c : {lm, dogleg, subspace, cgnr, identity}) {
    identities.insert(MakeSolver(SolverKind::kCeres, c)->Identity());
  }
  EXPECT_EQ(identities.size(), 5u);
  Graph moved = g;
  moved.nodes[2].theta = std::nextafter(moved.nodes[2].theta, 10.0);
  EXPECT_NE(key, SolveCache::KeyOf("spa", moved.nodes, moved.edges));
  Graph reweighted = g;
  reweighted.edges[1].constraint.information(0, 2) += 1e-12;
  EXPECT_NE(key, SolveCache::KeyOf("spa", reweighted.nodes, reweighted.edges));
  Graph remeasured = g;
  remeasured.edges[3].constraint.measurement.y += 1e-12;
  EXPECT_NE(key, SolveCache::KeyOf("spa", remeasured.nodes, remeasured.edges));
  Graph fewer = g;
  fewer.edges.pop_back();
  EXPECT_NE(key, SolveCache::KeyOf("spa", fewer.nodes, fewer.edges));
}

// A hit counts as a use: eviction drops the least recently used entries first.
TEST(SolveCache, EvictionKeepsRecentlyUsedSolves) {
  Graph g;
  const std::size_t one_entry = SolveCache::KeyOf("spa", g.nodes, g.edges).size() * 8 + 4 * sizeof(Pose2) + 256;
  SolveCache cache(2 * one_entry + one_entry / 2);  // room for two
  std::vector<std::vector<std::uint64_t>> keys;
  for (int k = 0; k < 3; ++k) {
    Graph v = g;
    v.nodes[1].x += 0.01 * k;
    keys.push_back(SolveCache::KeyOf("spa", v.nodes, v.edges));
  }
  cache.Store(keys[0], {{}, g.nodes, {}});
  cache.Store(keys[1], {{}, g.nodes, {}});
  EXPECT_TRUE(cache.Find(keys[0]).has_value());  // A used after B was stored
  cache.Store(keys[2], {{}, g.nodes, {}});       // evicts B, not A
  EXPECT_EQ(cache.counters().evictions, 1u);
  EXPECT_TRUE(cache.Find(keys[0]).has_value());
  EXPECT_FALSE(cache.Find(keys[1]).has_value());
  EXPECT_TRUE(cache.Find(keys[2]).has_value());
}

TEST(SolveCache, BudgetEvictsButResultsStayExact) {
  const auto solver = MakeSolver(SolverKind::kSpa);
  Graph g;
  const std::size_t one_entry = SolveCache::KeyOf("spa", g.nodes, g.edges).size() * 8 + 4 * sizeof(Pose2) + 256;
  SolveCache cache(one_entry + one_entry / 2);  // room for one
  std::vector<Pose2> direct = g.nodes;
  solver->Solve(direct, g.edges);
  Graph other = g;
  other.nodes[1].x += 0.01;
  const auto key_g = SolveCache::KeyOf("spa", g.nodes, g.edges);
  const auto key_other = SolveCache::KeyOf("spa", other.nodes, other.edges);
  for (int round = 0; round < 3; ++round) {
    for (const auto* key : {&key_g, &key_other}) {
      const auto hit = cache.Find(*key);
      if (hit) {
        EXPECT_TRUE(key == &key_g ? SameBits(hit->nodes, direct) : !SameBits(hit->nodes, direct));
        continue;
      }
      std::vector<Pose2> nodes = key == &key_g ? g.nodes : other.nodes;
      const SolveSummary summary = solver->Solve(nodes, g.edges);
      cache.Store(*key, {summary, nodes, {}});
    }
  }
  EXPECT_GT(cache.counters().evictions, 0u);
  EXPECT_LE(cache.counters().entries, 1u);
  EXPECT_THROW(SolveCache(0), std::exception);
}

}  // namespace
}  // namespace slamtune::slam
