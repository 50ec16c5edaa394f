#include <gtest/gtest.h>

#include <vector>

#include "slamtune/report/figures/optimize_figures.h"
#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

TEST(ParameterSpacePanels, OnePerObjectiveThenLoopsThenTheTrueErrorWithGroundTruth) {
  const auto without = ParameterSpacePanels(testing::FakeOptimizeResult(false));
  ASSERT_EQ(without.size(), 4u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(without[k].colouring, SpaceColouring::kObjective);
    EXPECT_EQ(without[k].objective, k);
  }
  EXPECT_EQ(without[3].colouring, SpaceColouring::kLoopClosures);
  const auto with = ParameterSpacePanels(testing::FakeOptimizeResult(true));
  ASSERT_EQ(with.size(), 5u);
  EXPECT_EQ(with[4].colouring, SpaceColouring::kTranslationalError);
}

TEST(LoopClosureClasses, EachCountWhenFewRangesOtherwise) {
  EXPECT_TRUE(LoopClosureClasses({}, 6).empty());
  const auto few = LoopClosureClasses({3, 0, 3, 5}, 6);
  ASSERT_EQ(few.size(), 3u);
  EXPECT_EQ(few[0].lower, 0);
  EXPECT_EQ(few[0].upper, 0);
  EXPECT_EQ(few[2].lower, 5);
  std::vector<int> many;
  for (int i = 0; i < 40; ++i) many.push_back(i % 20);
  const auto ranges = LoopClosureClasses(many, 4);
  ASSERT_EQ(ranges.size(), 4u);
  EXPECT_EQ(ranges.front().lower, 0);
  EXPECT_EQ(ranges.back().upper, 19);
  for (std::size_t i = 1; i < ranges.size(); ++i) EXPECT_EQ(ranges[i].lower, ranges[i - 1].upper + 1);  // contiguous
  // One count dominating: never an empty or reversed class.
  const auto skewed = LoopClosureClasses({0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7}, 3);
  ASSERT_FALSE(skewed.empty());
  for (const auto& c : skewed) EXPECT_LE(c.lower, c.upper);
  EXPECT_EQ(skewed.back().upper, 7);
}

TEST(ParameterAxisLimits, WidenedForANearbyDefaultClampedForAFarOne) {
  const optim::Dimension r{"loop_search_maximum_distance", 2.0, 6.0, false};
  const AxisLimits plain = ParameterAxisLimits(r, {3.0, 5.0});
  EXPECT_LT(plain.lower, 2.0);
  EXPECT_GT(plain.upper, 6.0);
  EXPECT_LT(plain.upper, 6.5);                                 // a 4 % margin
  const AxisLimits near = ParameterAxisLimits(r, {3.0, 7.0});  // the default 1 m beyond the range
  EXPECT_GT(near.upper, 7.0);
  EXPECT_FALSE(PlaceOnAxis(7.0, near).clamped);
  const AxisLimits far = ParameterAxisLimits(r, {3.0, 30.0});  // would squeeze the search range
  EXPECT_EQ(far.upper, plain.upper);
  EXPECT_TRUE(PlaceOnAxis(30.0, far).clamped);
  const AxisLimits below = ParameterAxisLimits(r, {1.0});
  EXPECT_LT(below.lower, 1.0);
}

TEST(ScatterGridCandidates, EveryCandidateMarkedAndADefaultOutsideDrawnAtTheBorder) {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  const auto inside = ScatterGridCandidates(r);
  ASSERT_EQ(inside.size(), 4u);
  EXPECT_EQ(inside[0].name, "recommended");
  EXPECT_EQ(inside[2].name, "default");
  EXPECT_EQ(inside[2].x, std::vector<double>{4.0});
  EXPECT_EQ(inside[2].marker, Marker::kSquare);
  // The default far beyond r's range: drawn just inside the axes with a grey triangle behind it,
  // its legend entry saying which value lies outside.
  for (auto& c : r.candidates)
    if (c.label == "default") c.record.params["loop_search_maximum_distance"] = 30.0;
  const auto outside = ScatterGridCandidates(r);
  ASSERT_EQ(outside.size(), 5u);
  const Series& triangle = outside[0];
  EXPECT_EQ(triangle.marker, Marker::kTriangle);
  EXPECT_EQ(triangle.name, "outside the axes: at the border");
  const Series& d = outside[3];
  EXPECT_EQ(d.name, "default (r=30: outside)");
  EXPECT_EQ(d.marker, Marker::kSquare);
  ASSERT_EQ(d.x.size(), 1u);
  EXPECT_LT(d.x[0], 6.0 + 0.04 * 4.0);  // inside the axes (the search range plus its margin)
  EXPECT_GT(d.x[0], 5.5);
  EXPECT_EQ(d.y, std::vector<double>{10.0});
  EXPECT_EQ(triangle.x, d.x);
  EXPECT_EQ(triangle.y, d.y);
  EXPECT_EQ(outside[1].name, "recommended");  // the others stay as they were
  EXPECT_EQ(outside[1].marker, Marker::kStar);
  optim::OptimizeResult three = testing::FakeOptimizeResult(false);
  three.space.dimensions.push_back({"loop_match_minimum_response_coarse", 0.5, 0.9, false});
  EXPECT_TRUE(ScatterGridCandidates(three).empty());
}

}  // namespace
}  // namespace slamtune::report
