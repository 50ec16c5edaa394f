#include "slamtune/report/figures/optimize_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

// A result whose snapshots hold a tight front and one individual whose map broke, far off.
optim::OptimizeResult FrontAndOutlier() {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  r.objectives = optim::ObjectiveSet(optim::ObjectiveSetKind::kPaper);
  r.candidates.clear();
  optim::GenerationSnapshot s;
  s.generation = 1;
  s.objectives = {{0.10, 1000, 12}, {0.11, 900, 14}, {0.12, 950, 10}, {0.115, 1200, 15}, {0.9, 90000, 400}};
  s.decisions.assign(s.objectives.size(), {3.0, 10.0});
  r.snapshots = {s};
  return r;
}

TEST(ObjectiveLimits, FitTheFrontNotTheFarWorstPoint) {
  const optim::OptimizeResult r = FrontAndOutlier();
  const auto limits = ObjectiveLimits(r);
  ASSERT_EQ(limits.size(), 3u);
  // The front: the first three (the fourth is dominated by the first, the fifth by all).
  ASSERT_TRUE(limits[1].has_value());
  EXPECT_LT(limits[1]->lower, 900);
  EXPECT_GT(limits[1]->upper, 1000);
  EXPECT_LT(limits[1]->upper, 1200);  // the dominated 1200 and the broken 90000 lie outside
  EXPECT_GT(limits[2]->upper, 15);    // the dominated 15 lies within one front range (4) of 14
  EXPECT_LT(limits[2]->upper, 20);
  // From the front's best value to one front range beyond its worst, with an 8 % margin.
  EXPECT_NEAR(limits[1]->lower, 900 - 0.08 * 200, 1e-9);
  EXPECT_NEAR(limits[1]->upper, 1100 + 0.08 * 200, 1e-9);
}

TEST(ObjectiveLimits, IncludeTheRecommendedAndKneeSets) {
  optim::OptimizeResult r = FrontAndOutlier();
  optim::Candidate rec;
  rec.label = "recommended";
  rec.record = testing::FakeRecord(3.0, 10, 0.0, false);
  optim::Candidate worst;
  worst.label = "worst";
  worst.record = testing::FakeRecord(6.0, 6, 1.0, false);
  worst.record.corner_pixels = 1e6;
  r.candidates = {rec, worst};
  const auto limits = ObjectiveLimits(r);
  const double rec_nc = r.objectives.Values(rec.record)[1];
  EXPECT_LE(limits[1]->lower, std::min(rec_nc, 900.0));
  EXPECT_LT(limits[1]->upper, 1e5);  // the worst set stays out
}

TEST(PopulationFigure, SameAxesForEveryGeneration) {
  const optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  const cv::Mat a = PopulationFigure(r.snapshots.front(), r, FigureOptions{});
  const cv::Mat b = PopulationFigure(r.snapshots.back(), r, FigureOptions{});
  EXPECT_EQ(a.size(), b.size());
}

TEST(CandidateMapPanels, OnePanelPerParameterSet) {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  EXPECT_EQ(CandidateMapPanels(r, FigureOptions{}).size(), 4u);
  r.candidates[1].record = r.candidates[0].record;  // the knee is the recommended set
  const auto panels = CandidateMapPanels(r, FigureOptions{});
  ASSERT_EQ(panels.size(), 3u);
  EXPECT_EQ(panels[0].group.label, "recommended = knee");
  EXPECT_FALSE(panels[0].image.empty());
}

optim::OptimizeResult WithThreeParameters() {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  r.space.dimensions.push_back({"loop_match_minimum_response_coarse", 0.5, 0.9, false});
  return r;
}

TEST(ParameterSpaceViewOf, ByTheNumberOfSearchedParameters) {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  EXPECT_EQ(ParameterSpaceViewOf(r), ParameterSpaceView::kScatterGrid);
  EXPECT_EQ(ParameterSpaceViewOf(WithThreeParameters()), ParameterSpaceView::kParallelCoordinates);
  r.space.dimensions.pop_back();
  EXPECT_EQ(ParameterSpaceViewOf(r), ParameterSpaceView::kSlices);
  r.space.dimensions.clear();
  EXPECT_EQ(ParameterSpaceViewOf(r), ParameterSpaceView::kNone);
  r = testing::FakeOptimizeResult(false);
  r.evaluations.clear();
  EXPECT_EQ(ParameterSpaceViewOf(r), ParameterSpaceView::kNone);
}

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
  EXPECT_TRUE(ScatterGridCandidates(WithThreeParameters()).empty());
}

// Pixels of exactly `colour` in a rectangle of `image`.
int CountColourIn(const cv::Mat& image, const cv::Rect& area, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image(area), colour, colour, mask);
  return cv::countNonZero(mask);
}

TEST(ParameterSpaceFigure, TwoParametersAPanelPerColouringWithTheCandidatesInEach) {
  const FigureOptions f;
  const int pad = GridOptions{}.padding;
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  const cv::Mat grid = ParameterSpaceFigure(r, f);
  ASSERT_FALSE(grid.empty());
  // Three objectives, loop closures and the shared legend: 3 + 2 cells.
  EXPECT_EQ(grid.cols, 3 * f.panel_width + 4 * pad);
  const int title_h = grid.rows - 2 * f.panel_height - 3 * pad;
  EXPECT_GT(title_h, 0);
  EXPECT_LT(title_h, 60);
  auto cell = [&](int i, int width) {
    return cv::Rect(pad + (i % 3) * (f.panel_width + pad), title_h + pad + (i / 3) * (f.panel_height + pad), width,
                    f.panel_height);
  };
  // The recommended star (vermillion) in the data area (left half) of every scatter panel.
  for (int i = 0; i < 4; ++i) EXPECT_GT(CountColourIn(grid, cell(i, f.panel_width / 2), PaletteColour(1)), 10) << i;
  EXPECT_GT(CountColourIn(grid, cell(4, f.panel_width), PaletteColour(1)), 0);  // and in the legend
  r.candidates.clear();
  const cv::Mat bare = ParameterSpaceFigure(r, f);
  EXPECT_EQ(CountColourIn(bare, cell(0, f.panel_width / 2), PaletteColour(1)), 0);
  // With ground truth, a fifth scatter panel fills the grid.
  const cv::Mat gt = ParameterSpaceFigure(testing::FakeOptimizeResult(true), f);
  EXPECT_EQ(gt.size(), grid.size());
  EXPECT_GT(CountColourIn(gt, cell(4, f.panel_width / 2), PaletteColour(1)), 10);
}

TEST(ParameterSpaceFigure, ParallelCoordinatesForThreeParametersWithTheRecommendationDrawnThick) {
  const FigureOptions f;
  optim::OptimizeResult r = WithThreeParameters();
  const cv::Mat figure = ParameterSpaceFigure(r, f);
  ASSERT_FALSE(figure.empty());
  EXPECT_EQ(figure.cols, 3 * f.panel_width + 4 * GridOptions{}.padding);
  EXPECT_EQ(figure.rows, f.panel_height + f.panel_height / 2);
  const cv::Rect all(0, 0, figure.cols, figure.rows);
  const int with = CountColourIn(figure, all, PaletteColour(1));
  EXPECT_GT(with, 1000);  // a 4 px line across the figure
  r.candidates.clear();
  EXPECT_LT(CountColourIn(ParameterSpaceFigure(r, f), all, PaletteColour(1)), with / 4);
  // Not the slices of the first objective any more.
  const cv::Mat slices = ObjectiveAgainstParameters(WithThreeParameters(), 0, f);
  EXPECT_NE(figure.size(), slices.size());
}

TEST(ObjectiveAgainstParameters, OnePanelPerParameterForEveryObjective) {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  const cv::Mat first = ObjectiveAgainstParameters(r, 0, FigureOptions{});
  const cv::Mat last = ObjectiveAgainstParameters(r, 2, FigureOptions{});
  ASSERT_FALSE(first.empty());
  ASSERT_FALSE(last.empty());
  EXPECT_GT(first.cols, 2 * FigureOptions{}.panel_width);  // two panels in a row
  EXPECT_LT(first.cols, 3 * FigureOptions{}.panel_width);
  EXPECT_EQ(first.size(), last.size());
  EXPECT_GT(cv::norm(first, last, cv::NORM_L1), 0.0);  // other values on the y axes
  EXPECT_TRUE(ObjectiveAgainstParameters(r, 3, FigureOptions{}).empty());
  // With one searched parameter, the parameter-space figure is the first objective's slice.
  r.space.dimensions.pop_back();
  EXPECT_EQ(cv::norm(ParameterSpaceFigure(r, FigureOptions{}), ObjectiveAgainstParameters(r, 0, FigureOptions{}),
                     cv::NORM_INF),
            0.0);
}

TEST(HistoryFigure, ObjectivePanelsAndTheHypervolume) {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  const cv::Mat figure = HistoryFigure(r, FigureOptions{});
  ASSERT_FALSE(figure.empty());
  EXPECT_GT(figure.cols, 2 * FigureOptions{}.panel_width);  // 2 x 2 panels
  EXPECT_GT(figure.rows, 2 * FigureOptions{}.panel_height);
  r.history = {};
  EXPECT_TRUE(HistoryFigure(r, FigureOptions{}).empty());
  // A generation without any successful run leaves a gap, not an error.
  r = testing::FakeOptimizeResult(false);
  r.history.generations[2].best.assign(3, std::nan(""));
  r.history.generations[2].hypervolume = 0.0;
  EXPECT_FALSE(HistoryFigure(r, FigureOptions{}).empty());
}

}  // namespace
}  // namespace slamtune::report
