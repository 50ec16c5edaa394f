#include "slamtune/report/figures/map_panels.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "slamtune/common/error.h"

namespace slamtune::report {
namespace {

io::MapImage UnknownMap(int w, int h) { return io::UniformMap(w, h, io::kMapUnknown); }

TEST(KnownBounds, BoxesTheKnownCellsWithMargin) {
  io::MapImage m = UnknownMap(100, 50);
  m.pixels[20 * 100 + 30] = io::kMapOccupied;
  m.pixels[25 * 100 + 40] = io::kMapFree;
  EXPECT_EQ(KnownBounds(m, 0), cv::Rect(30, 20, 11, 6));
  EXPECT_EQ(KnownBounds(m, 5), cv::Rect(25, 15, 21, 16));
  EXPECT_EQ(KnownBounds(m, 100), cv::Rect(0, 0, 100, 50));  // clipped to the image
  EXPECT_EQ(KnownBounds(UnknownMap(8, 4), 2), cv::Rect(0, 0, 8, 4));
}

// Pixels of the grey level `v`.
int CountGrey(const cv::Mat& bgr, std::uint8_t v) {
  cv::Mat mask;
  cv::inRange(bgr, cv::Scalar(v, v, v), cv::Scalar(v, v, v), mask);
  return cv::countNonZero(mask);
}

TEST(RenderMapPanel, CropsScalesAndShowsWalls) {
  io::MapImage m = UnknownMap(200, 200);
  for (int r = 90; r < 110; ++r)
    for (int c = 50; c < 150; ++c) m.pixels[r * 200 + c] = io::kMapFree;
  io::MapImage walled = m;
  for (int c = 50; c < 150; ++c) walled.pixels[100 * 200 + c] = io::kMapOccupied;  // one cell thick
  MapPanelOptions o;
  o.height = 40;  // the 20-row known area, doubled (nearest neighbour)
  o.crop_margin = 0;
  const cv::Mat plain = RenderMapPanel(m, "knee", "r=3 g=10", o);
  const cv::Mat panel = RenderMapPanel(walled, "knee", "r=3 g=10", o);
  EXPECT_EQ(panel.type(), CV_8UC3);
  EXPECT_EQ(panel.size(), plain.size());
  // Cropped to 100 x 20 cells and doubled: 200 x 40 px of map, the wall 200 x 2 px of black.
  EXPECT_EQ(CountGrey(panel, io::kMapOccupied) - CountGrey(plain, io::kMapOccupied), 200 * 2);
  EXPECT_EQ(CountGrey(plain, io::kMapFree), 200 * 40);
  EXPECT_EQ(plain.cols, 200 + 2 + 2 * 6);  // map, frame and padding: the unknown border was cropped away
}

TEST(RenderMapPanel, EmptyMapGivesAPlaceholderOfTheSameHeight) {
  MapPanelOptions o;
  o.height = 100;
  io::MapImage m = UnknownMap(40, 40);
  m.pixels[0] = io::kMapFree;
  const cv::Mat real = RenderMapPanel(m, "default", "", o);
  const cv::Mat none = RenderMapPanel(io::MapImage{}, "default", "", o);
  EXPECT_EQ(real.rows, none.rows);
  EXPECT_FALSE(HasMap(io::MapImage{}));
}

TEST(ScaleBarLength, RoundLengthOfAtMostAQuarterOfTheWidth) {
  EXPECT_DOUBLE_EQ(ScaleBarLength(20.0, 600), 5.0);    // 30 m wide: at most 7.5 m
  EXPECT_DOUBLE_EQ(ScaleBarLength(20.0, 400), 5.0);    // 20 m wide: at most 5 m
  EXPECT_DOUBLE_EQ(ScaleBarLength(20.0, 390), 2.0);    // 19.5 m wide: 4.875 m
  EXPECT_DOUBLE_EQ(ScaleBarLength(2.0, 1000), 100.0);  // 500 m wide: 125 m
  EXPECT_DOUBLE_EQ(ScaleBarLength(1000.0, 400), 0.1);  // 0.4 m wide
}

int CountVermillion(const cv::Mat& bgr) {
  cv::Mat mask;
  cv::inRange(bgr, cv::Scalar(0, 80, 200), cv::Scalar(20, 110, 225), mask);
  return cv::countNonZero(mask);
}

TEST(RenderMapPanel, DrawsLoopClosuresAndPathInTheMapsFrameAndAScaleBar) {
  io::MapImage m = UnknownMap(200, 100);  // 10 m x 5 m at 5 cm, origin (-1, -2)
  m.resolution = 0.05;
  m.origin = {-1.0, -2.0, 0.0};
  for (auto& p : m.pixels) p = io::kMapFree;
  MapPanelOptions o;
  o.height = 100;  // 1:1
  o.crop = false;
  const cv::Mat plain = RenderMapPanel(m, "knee", "", o);
  MapOverlay overlay;
  overlay.segments.push_back({0.0, 0.0, 4.0, 0.0, "725"});
  overlay.path = {{0.0, 1.0}, {8.0, 1.0}};
  const cv::Mat drawn = RenderMapPanel(m, "knee", "", o, overlay);
  ASSERT_EQ(drawn.size(), plain.size());
  EXPECT_EQ(CountVermillion(plain), 0);
  EXPECT_GT(CountVermillion(drawn), 80);  // the 80 px line at least
  // The segment lies on the row of y = 0 m: 40 cells below the top edge (y = 3 m) of the map.
  // Find the map's frame: the body starts one pixel inside it; locate the line's row by colour.
  int best_row = -1, best = 0;
  for (int r = 0; r < drawn.rows; ++r) {
    const int n = CountVermillion(drawn.row(r));
    if (n > best) best = n, best_row = r;
  }
  int top = -1;  // the first row of the map body: the first free-grey pixel of column x = the middle
  for (int r = 0; r < drawn.rows && top < 0; ++r) {
    const cv::Vec3b v = drawn.at<cv::Vec3b>(r, drawn.cols / 2);
    if (v[0] == io::kMapFree && v[1] == io::kMapFree && v[2] == io::kMapFree) top = r;
  }
  ASSERT_GE(top, 0);
  EXPECT_NEAR(best_row - top, 60, 2);  // y = 0 m is 3 m (60 cells) below the map's top (y = 3 m)
  // The scale bar takes a row under the map.
  o.scale_bar = false;
  EXPECT_LT(RenderMapPanel(m, "knee", "", o).rows, plain.rows);
}

TEST(RenderMapPanel, WrapsALongCaptionToTheMapsWidth) {
  io::MapImage m = UnknownMap(300, 100);
  for (auto& p : m.pixels) p = io::kMapFree;
  MapPanelOptions o;
  o.height = 100;
  o.crop = false;
  std::string caption;
  for (int i = 0; i < 40; ++i) caption += "parameter_" + std::to_string(i) + "=0.5 ";
  const cv::Mat panel = RenderMapPanel(m, "recommended", caption, o);
  EXPECT_LE(panel.cols, 320 + 2 * 6);
  EXPECT_GT(panel.rows, RenderMapPanel(m, "recommended", "short", o).rows + 40);  // several lines
}

TEST(MapPanelOptions, ValidateNamesTheField) {
  MapPanelOptions o;
  o.height = 5;
  try {
    o.Validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("MapPanelOptions.height = 5"), std::string::npos);
  }
}

}  // namespace
}  // namespace slamtune::report
