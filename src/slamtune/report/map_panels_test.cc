#include "slamtune/report/map_panels.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "slamtune/common/error.h"

namespace slamtune::report {
namespace {

io::MapImage UnknownMap(int w, int h) {
  io::MapImage m;
  m.width = w;
  m.height = h;
  m.pixels.assign(static_cast<std::size_t>(w) * h, io::kMapUnknown);
  return m;
}

TEST(KnownBounds, BoxesTheKnownCellsWithMargin) {
  io::MapImage m = UnknownMap(100, 50);
  m.pixels[20 * 100 + 30] = io::kMapOccupied;
  m.pixels[25 * 100 + 40] = io::kMapFree;
  EXPECT_EQ(KnownBounds(m, 0), cv::Rect(30, 20, 11, 6));
  EXPECT_EQ(KnownBounds(m, 5), cv::Rect(25, 15, 21, 16));
  EXPECT_EQ(KnownBounds(m, 100), cv::Rect(0, 0, 100, 50));   // clipped to the image
  EXPECT_EQ(KnownBounds(UnknownMap(8, 4), 2), cv::Rect(0, 0, 8, 4));
}

int CountColour(const cv::Mat& bgr, std::uint8_t v) {
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
  EXPECT_EQ(CountColour(panel, io::kMapOccupied) - CountColour(plain, io::kMapOccupied), 200 * 2);
  EXPECT_EQ(CountColour(plain, io::kMapFree), 200 * 40);
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
