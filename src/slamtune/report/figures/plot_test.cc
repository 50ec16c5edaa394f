#include "slamtune/report/figures/plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::report {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool IsWhite(const cv::Mat& image, cv::Point2d p) {
  const cv::Vec3b v = image.at<cv::Vec3b>(static_cast<int>(std::lround(p.y)), static_cast<int>(std::lround(p.x)));
  return v == cv::Vec3b(255, 255, 255);
}

int NonWhiteInside(const cv::Mat& image, const cv::Rect& area) {
  cv::Mat grey;
  cv::Mat inner = image(cv::Rect(area.x + 1, area.y + 1, area.width - 2, area.height - 2));
  cv::Mat mask;
  cv::inRange(inner, cv::Scalar(255, 255, 255), cv::Scalar(255, 255, 255), mask);
  return inner.rows * inner.cols - cv::countNonZero(mask);
}

TEST(RenderPlot, ImageHasRequestedSizeAndPointsAreDrawn) {
  const Series s = MakeSeries("pop", {1.0, 2.0, 3.0}, {10.0, 30.0, 20.0});
  PlotOptions o;
  o.width = 500;
  o.height = 300;
  o.title = "title";
  o.x_label = "x";
  o.y_label = "y";
  o.grid = false;
  const RenderedPlot r = RenderPlot({s}, o);
  EXPECT_EQ(r.image.cols, 500);
  EXPECT_EQ(r.image.rows, 300);
  EXPECT_EQ(r.image.type(), CV_8UC3);
  EXPECT_EQ(r.points_drawn, 3);
  for (std::size_t i = 0; i < s.x.size(); ++i) EXPECT_FALSE(IsWhite(r.image, r.ToPixel(s.x[i], s.y[i])));
  // Away from the points (and with no grid), the data area is white.
  EXPECT_TRUE(IsWhite(r.image, r.ToPixel(1.4, 27.0)));
  EXPECT_TRUE(r.plot_area.x > 0 && r.plot_area.br().x < 500 && r.plot_area.br().y < 300);
}

TEST(RenderPlot, LinesConnectPointsAndSeriesGetDistinctColours) {
  const Series a = MakeSeries("a", {0.0, 10.0}, {0.0, 10.0}, SeriesStyle::kLine);
  const Series b = MakeSeries("b", {0.0, 10.0}, {10.0, 0.0}, SeriesStyle::kLine);
  PlotOptions o;
  o.grid = false;
  const RenderedPlot r = RenderPlot({a, b}, o);
  EXPECT_FALSE(IsWhite(r.image, r.ToPixel(2.5, 2.5)));  // on line a
  EXPECT_FALSE(IsWhite(r.image, r.ToPixel(2.5, 7.5)));  // on line b
  EXPECT_TRUE(IsWhite(r.image, r.ToPixel(2.5, 5.0)));   // between them
  EXPECT_NE(PaletteColour(0), PaletteColour(1));
  EXPECT_NE(MarkerFor(0), MarkerFor(1));
  const cv::Point2d pa = r.ToPixel(2.5, 2.5);
  const cv::Point2d pb = r.ToPixel(2.5, 7.5);
  EXPECT_NE(r.image.at<cv::Vec3b>(std::lround(pa.y), std::lround(pa.x)),
            r.image.at<cv::Vec3b>(std::lround(pb.y), std::lround(pb.x)));
}

TEST(RenderPlot, DegenerateDataDoesNotCrash) {
  PlotOptions o;
  o.width = 200;
  o.height = 150;
  const std::vector<std::vector<Series>> cases = {
      {},                                                  // no series
      {MakeSeries("empty", {}, {})},                       // an empty series
      {MakeSeries("", {4.0}, {4.0})},                      // one point
      {MakeSeries("", {1.0, 1.0, 1.0}, {2.0, 2.0, 2.0})},  // all equal
      {MakeSeries("", {kNaN, 1.0}, {1.0, kNaN})},          // nothing finite
      {MakeSeries("", {0.0, 1e300}, {-1e300, 1e300}, SeriesStyle::kLineAndMarkers)},
      {MakeSeries("", {-1.7e308, 1.7e308}, {0.0, 1.0}, SeriesStyle::kLineAndMarkers)},
  };
  for (const auto& c : cases) {
    const RenderedPlot r = RenderPlot(c, o);
    EXPECT_EQ(r.image.size(), cv::Size(200, 150));
    EXPECT_LT(r.x_axis.lower, r.x_axis.upper);
    EXPECT_LT(r.y_axis.lower, r.y_axis.upper);
    EXPECT_TRUE(std::isfinite(r.x_axis.lower) && std::isfinite(r.x_axis.upper));
    EXPECT_TRUE(std::isfinite(r.y_axis.lower) && std::isfinite(r.y_axis.upper));
  }
  const RenderedPlot one = RenderPlot({MakeSeries("", {4.0}, {4.0})}, o);
  EXPECT_FALSE(IsWhite(one.image, one.ToPixel(4.0, 4.0)));
}

TEST(RenderPlot, NaNPointsAreSkippedAndCounted) {
  PlotOptions o;
  o.grid = false;
  const RenderedPlot r =
      RenderPlot({MakeSeries("", {1.0, kNaN, 3.0, 4.0}, {1.0, 2.0, kNaN, 4.0}, SeriesStyle::kLineAndMarkers)}, o);
  EXPECT_EQ(r.points_drawn, 2);
  EXPECT_EQ(r.points_skipped, 2);
  // The line does not bridge the gap between (1, 1) and (4, 4).
  EXPECT_TRUE(IsWhite(r.image, r.ToPixel(2.5, 2.5)));
}

TEST(RenderPlot, FixedLimitsClipOutsidePoints) {
  PlotOptions o;
  o.x_limits = AxisLimits{0.0, 1.0};
  o.y_limits = AxisLimits{0.0, 1.0};
  const RenderedPlot r = RenderPlot({MakeSeries("", {0.5, 5.0}, {0.5, 0.5})}, o);
  EXPECT_EQ(r.points_drawn, 1);
  EXPECT_EQ(r.points_clipped, 1);
  EXPECT_DOUBLE_EQ(r.x_axis.lower, 0.0);
  EXPECT_DOUBLE_EQ(r.x_axis.upper, 1.0);
}

TEST(RenderPlot, WholeNumberTicksLeaveOutFractions) {
  PlotOptions o;
  o.x_limits = AxisLimits{0.0, 2.0};  // three generations: nice ticks would be 0, 0.5, ..., 2
  const std::vector<Series> s = {MakeSeries("", {0, 1, 2}, {3, 1, 2})};
  ASSERT_GT(RenderPlot(s, o).x_axis.values.size(), 3u);
  o.x_whole_numbers = true;
  const RenderedPlot r = RenderPlot(s, o);
  EXPECT_EQ(r.x_axis.values, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(r.x_axis.labels, (std::vector<std::string>{"0", "1", "2"}));
  EXPECT_DOUBLE_EQ(r.x_axis.upper, 2.0);
}

TEST(RenderPlot, IsDeterministic) {
  const std::vector<Series> s = {MakeSeries("a", {1, 2, 3}, {3, 1, 2})};
  PlotOptions o;
  o.title = "same";
  EXPECT_EQ(cv::norm(RenderPlot(s, o).image, RenderPlot(s, o).image, cv::NORM_INF), 0.0);
}

TEST(RenderPlot, LegendIsDrawnRightOfTheAxes) {
  PlotOptions o;
  const RenderedPlot with = RenderPlot({MakeSeries("a long legend entry", {1}, {1})}, o);
  const RenderedPlot without = RenderPlot({MakeSeries("", {1}, {1})}, o);
  EXPECT_LT(with.plot_area.width, without.plot_area.width);
  const cv::Rect legend(with.plot_area.br().x + 1, with.plot_area.y, o.width - with.plot_area.br().x - 1, 30);
  EXPECT_GT(NonWhiteInside(with.image, legend), 0);
}

TEST(RenderLegend, ListsTheNamedSeriesOnly) {
  Series a = MakeSeries("recommended", {1.0}, {1.0});
  a.colour = cv::Scalar(0, 94, 213);
  Series hidden = MakeSeries("", {2.0}, {2.0});
  hidden.colour = cv::Scalar(0, 255, 0);
  PlotOptions o;
  o.width = 300;
  o.height = 200;
  o.title = "In every panel";
  const cv::Mat legend = RenderLegend({a, hidden}, o);
  ASSERT_EQ(legend.size(), cv::Size(300, 200));
  cv::Mat vermillion, green;
  cv::inRange(legend, a.colour.value(), a.colour.value(), vermillion);
  cv::inRange(legend, hidden.colour.value(), hidden.colour.value(), green);
  EXPECT_GT(cv::countNonZero(vermillion), 0);
  EXPECT_EQ(cv::countNonZero(green), 0);
  EXPECT_LT(NonWhiteInside(legend, cv::Rect(0, 0, 300, 200)), 300 * 200 / 4);
  EXPECT_EQ(NonWhiteInside(RenderLegend({hidden}, PlotOptions{}), cv::Rect(0, 0, 640, 480)), 0);
}

TEST(PlotOptions, ValidateNamesTheField) {
  PlotOptions o;
  o.width = 10;
  try {
    o.Validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("PlotOptions.width = 10"), std::string::npos);
  }
  PlotOptions limits;
  limits.y_limits = AxisLimits{2.0, 1.0};
  EXPECT_THROW(limits.Validate(), InputError);
}

TEST(PanelSize, ValidateNamesTheOwnersFieldAndPlotTakesSizeAndFont) {
  PanelSize small{100, 340, 0.45};
  EXPECT_EQ(slamtune::testing::ErrorMessageOf([&] { small.Validate("SweepReportOptions.panel"); }),
            "SweepReportOptions.panel.width = 100: must be >= 160 px");
  PanelSize tiny_font{460, 340, 0.0};
  EXPECT_THAT(slamtune::testing::ErrorMessageOf([&] { tiny_font.Validate("FigureOptions.panel"); }),
              ::testing::HasSubstr("FigureOptions.panel.font_scale = 0"));
  const PlotOptions o = PanelSize{460, 340, 0.6}.Plot();
  EXPECT_EQ(o.width, 460);
  EXPECT_EQ(o.height, 340);
  EXPECT_EQ(o.font_scale, 0.6);
  EXPECT_TRUE(o.title.empty());
  EXPECT_NO_THROW(PanelSize{}.Validate("FigureOptions.panel"));
}

TEST(ComposeGrid, PlacesPanelsInCells) {
  cv::Mat red(50, 80, CV_8UC3, cv::Scalar(0, 0, 255));
  cv::Mat grey(40, 60, CV_8UC1, cv::Scalar(0));
  GridOptions g;
  g.columns = 2;
  g.padding = 5;
  const cv::Mat grid = ComposeGrid({red, grey, red}, g);
  EXPECT_EQ(grid.cols, 2 * 80 + 3 * 5);
  EXPECT_EQ(grid.rows, 2 * 50 + 3 * 5);
  EXPECT_EQ(grid.at<cv::Vec3b>(5 + 25, 5 + 40), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(grid.at<cv::Vec3b>(5 + 25, 5 + 80 + 5 + 40), cv::Vec3b(0, 0, 0));      // grey panel, centred
  EXPECT_EQ(grid.at<cv::Vec3b>(5 + 2, 5 + 80 + 5 + 2), cv::Vec3b(255, 255, 255));  // outside it
  g.title = "Title";
  EXPECT_GT(ComposeGrid({red}, g).rows, 50 + 2 * 5);
}

}  // namespace
}  // namespace slamtune::report
