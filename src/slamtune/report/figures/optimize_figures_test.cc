#include "slamtune/report/figures/optimize_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

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

TEST(CandidateSeries, OneStylePerLabelAndOneForAnyOther) {
  auto series = [](const std::string& label) {
    optim::Candidate c;
    c.label = label;
    return CandidateSeries(c, 1.0, 2.0);
  };
  const Series recommended = series("recommended");
  EXPECT_EQ(recommended.name, "recommended");
  EXPECT_EQ(recommended.x, std::vector<double>{1.0});
  EXPECT_EQ(recommended.y, std::vector<double>{2.0});
  EXPECT_EQ(recommended.marker, Marker::kStar);
  EXPECT_EQ(*recommended.colour, PaletteColour(1));
  EXPECT_EQ(series("knee").marker, Marker::kDiamond);
  EXPECT_EQ(series("default").marker, Marker::kSquare);
  EXPECT_EQ(series("worst").marker, Marker::kCross);
  const Series other = series("best loop closure");
  EXPECT_EQ(other.marker, Marker::kPlus);
  EXPECT_EQ(*other.colour, PaletteColour(4));
  EXPECT_EQ(other.marker_size, 14);
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
  EXPECT_EQ(grid.cols, 3 * f.panel.width + 4 * pad);
  const int title_h = grid.rows - 2 * f.panel.height - 3 * pad;
  EXPECT_GT(title_h, 0);
  EXPECT_LT(title_h, 60);
  auto cell = [&](int i, int width) {
    return cv::Rect(pad + (i % 3) * (f.panel.width + pad), title_h + pad + (i / 3) * (f.panel.height + pad), width,
                    f.panel.height);
  };
  // The recommended star (vermillion) in the data area (left half) of every scatter panel.
  for (int i = 0; i < 4; ++i) EXPECT_GT(CountColourIn(grid, cell(i, f.panel.width / 2), PaletteColour(1)), 10) << i;
  EXPECT_GT(CountColourIn(grid, cell(4, f.panel.width), PaletteColour(1)), 0);  // and in the legend
  r.candidates.clear();
  const cv::Mat bare = ParameterSpaceFigure(r, f);
  EXPECT_EQ(CountColourIn(bare, cell(0, f.panel.width / 2), PaletteColour(1)), 0);
  // With ground truth, a fifth scatter panel fills the grid.
  const cv::Mat gt = ParameterSpaceFigure(testing::FakeOptimizeResult(true), f);
  EXPECT_EQ(gt.size(), grid.size());
  EXPECT_GT(CountColourIn(gt, cell(4, f.panel.width / 2), PaletteColour(1)), 10);
}

TEST(ParameterSpaceFigure, ParallelCoordinatesForThreeParametersWithTheRecommendationDrawnThick) {
  const FigureOptions f;
  optim::OptimizeResult r = WithThreeParameters();
  const cv::Mat figure = ParameterSpaceFigure(r, f);
  ASSERT_FALSE(figure.empty());
  EXPECT_EQ(figure.cols, 3 * f.panel.width + 4 * GridOptions{}.padding);
  EXPECT_EQ(figure.rows, f.panel.height + f.panel.height / 2);
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
  EXPECT_GT(first.cols, 2 * FigureOptions{}.panel.width);  // two panels in a row
  EXPECT_LT(first.cols, 3 * FigureOptions{}.panel.width);
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
  EXPECT_GT(figure.cols, 2 * FigureOptions{}.panel.width);  // 2 x 2 panels
  EXPECT_GT(figure.rows, 2 * FigureOptions{}.panel.height);
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
