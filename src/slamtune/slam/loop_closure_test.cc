#include "slamtune/slam/loop_closure.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "slamtune/slam/testing/chain_graph.h"

namespace slamtune::slam {
namespace {

using testing::ChainGraph;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

// The state ids of `refs`: the walk of one laser.
std::vector<int> All(const std::vector<Pose2>& refs) {
  std::vector<int> ids(refs.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
  return ids;
}

// The worked example of §6.5: scans 0..29, current 29, r = 2. Inside r: {0..3}, {10}, {15, 16},
// {26..29}; everything else 10 m away. linked = {26..29} through the sequential edges.
std::vector<Pose2> WorkedExampleRefs() {
  const std::set<int> inside{0, 1, 2, 3, 10, 15, 16, 26, 27, 28};
  std::vector<Pose2> refs;
  for (int i = 0; i < 29; ++i) refs.push_back(inside.count(i) ? Pose2{1.0, 0.01 * i, 0} : Pose2{10.0, 0, 0});
  refs.push_back({0, 0, 0});
  return refs;
}

TEST(FindPossibleLoopClosure, WorkedExampleWithG3) {
  const auto refs = WorkedExampleRefs();
  const PoseGraph g = ChainGraph(refs);
  const LoopSearchOptions options{2.0, 3};
  int cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, options, &cursor), ElementsAre(0, 1, 2, 3));
  EXPECT_EQ(cursor, 4);  // not advanced past the out-of-range scan
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, options, &cursor), IsEmpty());
  EXPECT_EQ(cursor, 30);
}

TEST(FindPossibleLoopClosure, WorkedExampleWithG2AndG5) {
  const auto refs = WorkedExampleRefs();
  const PoseGraph g = ChainGraph(refs);
  int cursor = 0;
  const LoopSearchOptions g2{2.0, 2};
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, g2, &cursor), ElementsAre(0, 1, 2, 3));
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, g2, &cursor), ElementsAre(15, 16));
  EXPECT_EQ(cursor, 17);
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, g2, &cursor), IsEmpty());
  cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, {2.0, 5}, &cursor), IsEmpty());
}

TEST(FindPossibleLoopClosure, RunOneShortOfGIsSkipped) {
  const auto refs = WorkedExampleRefs();
  const PoseGraph g = ChainGraph(refs);
  int cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, {2.0, 4}, &cursor), ElementsAre(0, 1, 2, 3));
  cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, {2.0, 5}, &cursor), IsEmpty());
}

TEST(FindPossibleLoopClosure, LinkedScanInsideRResetsTheRun) {
  auto refs = WorkedExampleRefs();
  PoseGraph g = ChainGraph(refs);
  // A loop edge 2 -> 29 makes scans 0..3 linked to 29 within r: nothing left for g = 2 except 15, 16.
  g.LinkScans(2, 29, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kLoop);
  int cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 29, {2.0, 2}, &cursor), ElementsAre(15, 16));
  // A linked scan in the middle of a run resets the run without ending it. Scans 0, 2, 3 sit in
  // the band r^2 - 1e-6 < d^2 < r^2 + 1e-6 (candidates that the BFS never accepts); scan 1 is
  // linked to 29 by a loop edge.
  const double band = std::sqrt(4.0 - 0.5e-6);
  refs[0] = refs[2] = refs[3] = {band, 0, 0};
  refs[1] = {1, 0, 0};
  PoseGraph h = ChainGraph(refs);
  h.LinkScans(1, 29, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kLoop);
  cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(h, refs, All(refs), 29, {2.0, 2}, &cursor), ElementsAre(2, 3));
  EXPECT_EQ(cursor, 4);
  cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(h, refs, All(refs), 29, {2.0, 3}, &cursor), IsEmpty());
}

TEST(FindPossibleLoopClosure, ToleranceBandsOfSection62) {
  // r = 2. Scans 0..3 form a run inside r; scan 4 is outside; scan 5 is the current scan.
  // Scan 6 does not exist: the current scan is always the last vertex.
  const double r = 2.0;
  auto make = [&](double d2_first) {
    std::vector<Pose2> refs{{std::sqrt(d2_first), 0, 0}, {1, 0, 0}, {1, 0.1, 0}, {1, 0.2, 0}, {9, 0, 0}, {0, 0, 0}};
    return refs;
  };
  const LoopSearchOptions options{r, 4};
  // d^2 = r^2 + 0.5e-6 is inside (d^2 < r^2 + 1e-6): run of 4.
  {
    const auto refs = make(4.0 + 0.5e-6);
    PoseGraph g = ChainGraph(refs);
    int cursor = 0;
    EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 5, options, &cursor), ElementsAre(0, 1, 2, 3));
  }
  // d^2 = r^2 + 2e-6 is outside: the run is 1..3, too short.
  {
    const auto refs = make(4.0 + 2e-6);
    PoseGraph g = ChainGraph(refs);
    int cursor = 0;
    EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 5, options, &cursor), IsEmpty());
  }
  // Linked through an edge 0 -> 5 but inside the band (d^2 > r^2 - 1e-6): still a candidate.
  {
    const auto refs = make(4.0 - 0.5e-6);
    PoseGraph g = ChainGraph(refs);
    g.LinkScans(0, 5, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kLoop);
    int cursor = 0;
    EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 5, options, &cursor), ElementsAre(0, 1, 2, 3));
  }
  // Linked and d^2 = r^2 - 2e-6: the BFS accepts it, which links 1..3 too.
  {
    const auto refs = make(4.0 - 2e-6);
    PoseGraph g = ChainGraph(refs);
    g.LinkScans(0, 5, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kLoop);
    int cursor = 0;
    EXPECT_THAT(FindPossibleLoopClosure(g, refs, All(refs), 5, {r, 1}, &cursor), IsEmpty());
  }
}

// Two lasers taking turns (even state ids laser 0, odd laser 1), each scan linked to its laser's
// previous one; the current scan 13 is laser 1's. Each laser's walk is its own scans (§3.5), and
// on the other laser's walk the run pending at its end is returned whatever its length (§6.2).
TEST(FindPossibleLoopClosure, WalksOneLaserAndReturnsAnotherLasersPendingRun) {
  std::vector<Pose2> refs;
  for (int i = 0; i < 14; ++i) refs.push_back(i < 4 || i >= 10 ? Pose2{0.1 * i, 0, 0} : Pose2{20, 0, 0});
  PoseGraph g;
  for (const Pose2& p : refs) g.AddVertex(p);
  for (int i = 2; i < 14; ++i) g.LinkScans(i - 2, i, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kSequential);
  const std::vector<int> laser0{0, 2, 4, 6, 8, 10, 12};
  const std::vector<int> laser1{1, 3, 5, 7, 9, 11, 13};
  const LoopSearchOptions g2{2.0, 2};
  // Laser 0: {0, 2} then far scans, then {10, 12}, not linked to 13 (no edge between the lasers).
  int cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, laser0, 13, g2, &cursor), ElementsAre(0, 2));
  EXPECT_EQ(cursor, 2);
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, laser0, 13, g2, &cursor), ElementsAre(10, 12));
  EXPECT_EQ(cursor, 7);
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, laser0, 13, g2, &cursor), IsEmpty());
  // The pending run at the end comes back even when shorter than g.
  cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, laser0, 13, {2.0, 5}, &cursor), ElementsAre(10, 12));
  // Laser 1 (the current scan's): {1, 3} is a candidate; 11, 13 are linked to 13, nothing pends.
  cursor = 0;
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, laser1, 13, g2, &cursor), ElementsAre(1, 3));
  EXPECT_THAT(FindPossibleLoopClosure(g, refs, laser1, 13, g2, &cursor), IsEmpty());
  EXPECT_EQ(cursor, 7);
}

}  // namespace
}  // namespace slamtune::slam
