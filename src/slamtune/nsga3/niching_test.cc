#include "slamtune/nsga3/niching.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace slamtune::nsga3 {
namespace {

using ::testing::ElementsAre;
using ::testing::UnorderedElementsAre;

TEST(PerpendicularDistance, IsTheDistanceToTheLineNotToThePoint) {
  EXPECT_NEAR(PerpendicularDistance({1, 1}, {1, 0}), 1.0, 1e-12);
  EXPECT_NEAR(PerpendicularDistance({3, 3}, {0.5, 0.5}), 0.0, 1e-12);
  EXPECT_NEAR(PerpendicularDistance({1, 0}, {1, 1}), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(PerpendicularDistance({0, 0, 2}, {1, 0, 0}), 2.0, 1e-12);
}

TEST(Associate, PicksTheNearestReferenceLine) {
  const std::vector<std::vector<double>> refs = {{1, 0}, {0.5, 0.5}, {0, 1}};
  const Association a = Associate({{1, 0.1}, {0.4, 0.6}, {0.05, 2.0}, {2.0, 2.0}}, refs);
  EXPECT_THAT(a.reference, ElementsAre(0, 1, 2, 1));
  EXPECT_NEAR(a.distance[0], 0.1, 1e-12);
  EXPECT_NEAR(a.distance[1], std::sqrt(0.02), 1e-12);
  EXPECT_NEAR(a.distance[2], 0.05, 1e-12);
  EXPECT_NEAR(a.distance[3], 0.0, 1e-12);
}

// Three reference lines in 2-D; the last front holds members 0..3:
//   member 0 -> ref 1 (distance 0.3), member 1 -> ref 1 (0.1), member 2 -> ref 0, member 3 -> ref 2.
Association HandMadeAssociation() {
  Association a;
  a.reference = {1, 1, 0, 2};
  a.distance = {0.3, 0.1, 0.2, 0.2};
  return a;
}

TEST(SelectByNiching, EmptyNicheTakesItsClosestMember) {
  // rho = (1, 0, 2): reference 1 is the only least crowded one and its nearest member is 1.
  for (unsigned seed = 0; seed < 20; ++seed) {
    std::mt19937 rng(seed);
    const NicheSelection s = SelectByNiching(1, {1, 0, 2}, {0, 1, 2, 3}, HandMadeAssociation(), rng);
    EXPECT_THAT(s.chosen, ElementsAre(1));
    EXPECT_THAT(s.niche_count, ElementsAre(1, 1, 2));
  }
}

TEST(SelectByNiching, TiesBetweenLeastCrowdedPointsAreBrokenAtRandom) {
  // After member 1, rho = (1, 1, 2): reference 0 (member 2) and 1 (member 0, a random pick as
  // rho_1 = 1) tie; both outcomes occur over seeds, reference 2 (member 3) never.
  std::set<std::size_t> second_choices;
  for (unsigned seed = 0; seed < 40; ++seed) {
    std::mt19937 rng(seed);
    const NicheSelection s = SelectByNiching(2, {1, 0, 2}, {0, 1, 2, 3}, HandMadeAssociation(), rng);
    ASSERT_EQ(s.chosen.size(), 2u);
    EXPECT_EQ(s.chosen[0], 1u);
    second_choices.insert(s.chosen[1]);
  }
  EXPECT_THAT(second_choices, UnorderedElementsAre(0, 2));
}

TEST(SelectByNiching, CrowdedNicheIsServedLast) {
  std::mt19937 rng(7);
  const NicheSelection s = SelectByNiching(3, {1, 0, 2}, {0, 1, 2, 3}, HandMadeAssociation(), rng);
  EXPECT_THAT(s.chosen, UnorderedElementsAre(0, 1, 2));
  EXPECT_THAT(s.niche_count, ElementsAre(2, 2, 2));
}

TEST(SelectByNiching, ReferencePointsWithoutCandidatesAreExcluded) {
  // Reference 0 has rho = 0 but no member in the last front: it is excluded, and the choice
  // falls to reference 1 (rho = 5), whose members are then picked at random.
  Association a;
  a.reference = {1, 1, 1};
  a.distance = {0.1, 0.2, 0.3};
  std::set<std::size_t> picks;
  for (unsigned seed = 0; seed < 30; ++seed) {
    std::mt19937 rng(seed);
    const NicheSelection s = SelectByNiching(1, {0, 5, 5}, {0, 1, 2}, a, rng);
    EXPECT_GE(s.excluded_references, 1u);
    ASSERT_EQ(s.chosen.size(), 1u);
    picks.insert(s.chosen[0]);
  }
  EXPECT_EQ(picks.size(), 3u) << "rho >= 1: the member must be random, not the closest";
}

TEST(SelectByNiching, SameSeedSameChoice) {
  Association a;
  a.reference = {0, 0, 1, 1, 2, 2, 0, 1};
  a.distance = {0.5, 0.4, 0.3, 0.2, 0.1, 0.6, 0.7, 0.8};
  std::mt19937 r1(3), r2(3);
  const auto s1 = SelectByNiching(5, {1, 1, 1}, {0, 1, 2, 3, 4, 5, 6, 7}, a, r1);
  const auto s2 = SelectByNiching(5, {1, 1, 1}, {0, 1, 2, 3, 4, 5, 6, 7}, a, r2);
  EXPECT_EQ(s1.chosen, s2.chosen);
}

}  // namespace
}  // namespace slamtune::nsga3
