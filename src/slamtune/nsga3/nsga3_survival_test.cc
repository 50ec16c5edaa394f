#include "slamtune/nsga3/nsga3_survival.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace slamtune::nsga3 {
namespace {

using ::testing::ElementsAre;
using ::testing::UnorderedElementsAre;

const ReferencePoints kRefs2d = {{1, 0}, {0.5, 0.5}, {0, 1}};

TEST(SelectSurvivors, WholeFrontsThatFitExactlySurviveWithoutNiching) {
  // F1 = {0, 1}, F2 = {2, 3}; N = 2.
  const std::vector<std::vector<double>> f = {{0, 1}, {1, 0}, {1, 2}, {2, 1}};
  std::mt19937 rng(1);
  const SurvivalResult r = SelectSurvivors(f, 2, kRefs2d, NormalizationOptions{}, rng);
  EXPECT_THAT(r.survivors, UnorderedElementsAre(0, 1));
  EXPECT_EQ(r.fronts_used, 1u);
  EXPECT_EQ(r.niched, 0u);
  EXPECT_FALSE(r.normalization.has_value());
}

TEST(SelectSurvivors, LastFrontIsSplitByNiching) {
  // F1 = {(0,1), (1,0)} fills references 2 and 0; of F2 = {(1,2), (2,1), (1.5,1.5)} all lie
  // nearest to reference 1, which is empty, so its closest member (1.5, 1.5) must be taken.
  const std::vector<std::vector<double>> f = {{1, 2}, {0, 1}, {2, 1}, {1.5, 1.5}, {1, 0}, {5, 5}};
  for (unsigned seed = 0; seed < 10; ++seed) {
    std::mt19937 rng(seed);
    const SurvivalResult r = SelectSurvivors(f, 3, kRefs2d, NormalizationOptions{}, rng);
    EXPECT_THAT(r.survivors, ElementsAre(1, 4, 3));
    EXPECT_EQ(r.fronts_used, 2u);
    EXPECT_EQ(r.last_front_size, 3u);
    EXPECT_EQ(r.niched, 1u);
    ASSERT_TRUE(r.normalization.has_value());
    EXPECT_TRUE(r.normalization->hyperplane_rejection.empty());
    EXPECT_THAT(r.normalization->nadir, ElementsAre(1, 1));
  }
}

TEST(SelectSurvivors, NichingSpreadsTheLastFrontOverTheReferenceLines) {
  // One front of 7 points on the line f0 + f1 = 1; 3 survivors must cover the three lines:
  // the two ends and the point nearest (0.5, 0.5).
  const std::vector<std::vector<double>> f = {{0, 1},     {0.1, 0.9},   {0.3, 0.7}, {0.45, 0.55},
                                              {0.8, 0.2}, {0.95, 0.05}, {1, 0}};
  std::mt19937 rng(4);
  const SurvivalResult r = SelectSurvivors(f, 3, kRefs2d, NormalizationOptions{}, rng);
  EXPECT_THAT(r.survivors, UnorderedElementsAre(0, 3, 6));
}

}  // namespace
}  // namespace slamtune::nsga3
