#include "slamtune/slam/near_chains.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/slam/testing/chain_graph.h"

namespace slamtune::slam {
namespace {

using testing::ChainGraph;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

// `n` scans of one laser.
ScansByLaser OneLaser(std::size_t n) {
  ScansByLaser lasers;
  for (std::size_t i = 0; i < n; ++i) lasers.Add(0);
  return lasers;
}

TEST(ClosestInChain, FirstMemberWinsTies) {
  const std::vector<Pose2> refs{{1, 0, 0}, {-1, 0, 0}, {0, 2, 0}, {0, 0, 0}};
  const std::vector<int> chain{0, 1, 2};
  EXPECT_EQ(ClosestInChain(chain, refs, 3), 0);
  const std::vector<int> reversed{2, 1, 0};
  EXPECT_EQ(ClosestInChain(reversed, refs, 3), 1);
}

TEST(FindNearChains, RecentRunReachingTheScanIsInvalid) {
  // A straight run ending at scan 8 (the current one): the run near 8 reaches 8 itself.
  std::vector<Pose2> refs;
  for (int i = 0; i < 9; ++i) refs.push_back({0.5 * i, 0, 0});
  const PoseGraph g = ChainGraph(refs);
  EXPECT_THAT(FindNearChains(g, refs, OneLaser(refs.size()), 8, 1.0), IsEmpty());
}

TEST(FindNearChains, OlderPassConnectedWithinLIsAChain) {
  // Old pass 0..5 along y = 0; the robot leaves (6..9 far) and returns: 10, 11 near scan 2.
  std::vector<Pose2> refs{{-2, 0, 0}, {-1, 0, 0}, {0, 0, 0},  {1, 0, 0},  {2, 0, 0},   {3, 0, 0},
                          {3, 8, 0},  {0, 8, 0},  {-3, 8, 0}, {-3, 3, 0}, {0, 0.6, 0}, {0.2, 0.4, 0}};
  PoseGraph g = ChainGraph(refs);
  // Without a link to the old pass, only the recent run is near-linked: no valid chain.
  EXPECT_THAT(FindNearChains(g, refs, OneLaser(refs.size()), 11, 1.5), IsEmpty());
  // A loop edge 2 -> 10 connects the old pass within L.
  g.LinkScans(2, 10, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kLoop);
  const auto chains = FindNearChains(g, refs, OneLaser(refs.size()), 11, 1.5);
  ASSERT_EQ(chains.size(), 1u);
  // Members within 1.5 m of scan 11's reference (0.2, 0.4): scans 1, 2, 3 (distance of 0 is 2.2+).
  EXPECT_THAT(chains[0], ElementsAre(1, 2, 3));
}

TEST(FindNearChains, ChainBoundaryUsesStrictPlusTolerance) {
  // d^2 < L^2 + 1e-6 keeps a member exactly at L.
  std::vector<Pose2> refs{{5, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {9, 9, 0}, {0, 0, 0}};
  PoseGraph g = ChainGraph(refs);
  g.LinkScans(2, 4, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kLoop);
  auto chains = FindNearChains(g, refs, OneLaser(refs.size()), 4, 1.0);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_THAT(chains[0], ElementsAre(1, 2));
}

// Two lasers taking turns (even state ids laser 0, odd laser 1), each scan linked to its laser's
// previous one: a chain grows over the consecutive scans of its seed's laser only (§5.4, §3.5).
TEST(FindNearChains, ChainsFollowTheSeedsOwnLaser) {
  // Old pass 0..7 along y = 0, away (8..11), back near the old pass (12, 13); current scan 13.
  const std::vector<Pose2> refs{{-1.5, 0, 0}, {-1, 0, 0},  {-0.5, 0, 0}, {0, 0, 0},    {0.5, 0, 0},
                                {1, 0, 0},    {1.5, 0, 0}, {2, 0, 0},    {2, 9, 0},    {0, 9, 0},
                                {-2, 9, 0},   {-2, 5, 0},  {0, 0.5, 0},  {0.1, 0.4, 0}};
  const auto two_lasers = [&] {
    PoseGraph g;
    for (const Pose2& p : refs) g.AddVertex(p);
    for (int i = 2; i < static_cast<int>(refs.size()); ++i) {
      g.LinkScans(i - 2, i, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kSequential);
    }
    return g;
  };
  ScansByLaser lasers;
  for (std::size_t i = 0; i < refs.size(); ++i) lasers.Add(static_cast<int>(i % 2));
  PoseGraph g = two_lasers();
  EXPECT_THAT(FindNearChains(g, refs, lasers, 13, 1.5), IsEmpty());
  // A link from laser 0's scan 4 to the current scan (laser 1): the chain is laser 0's scans
  // within 1.5 m of scan 13 around the seed, skipping laser 1's scans in between.
  g.LinkScans(4, 13, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kNearChain);
  auto chains = FindNearChains(g, refs, lasers, 13, 1.5);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_THAT(chains[0], ElementsAre(2, 4, 6));
  // A link from laser 1's scan 3 instead: its own laser's neighbours, and the walk forward
  // reaches the current scan (laser 1's last) only through scans outside L, so it stays valid.
  g = two_lasers();
  g.LinkScans(3, 13, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kNearChain);
  chains = FindNearChains(g, refs, lasers, 13, 1.5);
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_THAT(chains[0], ElementsAre(1, 3, 5));
}

}  // namespace
}  // namespace slamtune::slam
