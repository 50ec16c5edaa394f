#include "slamtune/report/figures/parallel_coordinates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::report {
namespace {

const cv::Scalar kVermillion(0, 94, 213);

bool HasColourNear(const cv::Mat& image, cv::Point centre, int radius, const cv::Scalar& colour) {
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const cv::Point p = centre + cv::Point(dx, dy);
      if (p.x < 0 || p.y < 0 || p.x >= image.cols || p.y >= image.rows) continue;
      const cv::Vec3b v = image.at<cv::Vec3b>(p);
      if (std::abs(v[0] - colour[0]) < 8 && std::abs(v[1] - colour[1]) < 8 && std::abs(v[2] - colour[2]) < 8) {
        return true;
      }
    }
  }
  return false;
}

std::vector<ParallelAxis> ThreeAxes() {
  return {{"loop_search_maximum_distance", "m", {2.0, 6.0}}, {"g", "", {6.0, 20.0}}, {"n_c", "", {0.0, 1000.0}}};
}

TEST(PlaceOnAxis, InsideStaysOutsideGoesToTheNearerEnd) {
  const AxisLimits l{2.0, 6.0};
  EXPECT_EQ(PlaceOnAxis(3.5, l).value, 3.5);
  EXPECT_FALSE(PlaceOnAxis(3.5, l).clamped);
  EXPECT_FALSE(PlaceOnAxis(6.0, l).clamped);
  EXPECT_EQ(PlaceOnAxis(9.0, l).value, 6.0);
  EXPECT_TRUE(PlaceOnAxis(9.0, l).clamped);
  EXPECT_EQ(PlaceOnAxis(-1.0, l).value, 2.0);
  EXPECT_TRUE(PlaceOnAxis(-1.0, l).clamped);
  EXPECT_TRUE(std::isnan(PlaceOnAxis(std::nan(""), l).value));
  EXPECT_FALSE(PlaceOnAxis(std::nan(""), l).clamped);
}

TEST(WrapLabel, BreaksAtUnderscoresToFitTheWidth) {
  const std::string name = "correlation_search_space_smear_deviation";
  const int narrow = TextSize("correlation_search", 0.45).width;
  const auto lines = WrapLabel(name, narrow, 0.45);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines.front(), "correlation_search");
  std::string joined;
  for (const auto& l : lines) {
    EXPECT_LE(TextSize(l, 0.45).width, narrow) << l;
    joined += (joined.empty() ? "" : "_") + l;
  }
  EXPECT_EQ(joined, name);  // nothing lost, no separator at the start of a line
  EXPECT_EQ(WrapLabel(name, 10000, 0.45), std::vector<std::string>{name});
  EXPECT_EQ(WrapLabel("r", 1, 0.45), std::vector<std::string>{"r"});  // a long word stays whole
  EXPECT_TRUE(WrapLabel("", 100, 0.45).empty());
}

TEST(RenderParallelCoordinates, AxesSpreadAcrossTheImageAndLinesJoinTheValues) {
  ParallelCoordinatesOptions o;
  o.width = 900;
  o.height = 400;
  o.title = "three axes";
  const ParallelLine line{{4.0, 13.0, 500.0}, kVermillion, 3, false};
  const RenderedParallel r = RenderParallelCoordinates(ThreeAxes(), {line}, {{"recommended", kVermillion, 3}}, o);
  EXPECT_EQ(r.image.cols, 900);
  EXPECT_EQ(r.image.rows, 400);
  ASSERT_EQ(r.axis_x.size(), 3u);
  EXPECT_LT(r.axis_x[0], r.axis_x[1]);
  EXPECT_LT(r.axis_x[1], r.axis_x[2]);
  EXPECT_LT(r.axis_x[2], 900);
  EXPECT_LT(r.axis_top, r.axis_bottom);
  EXPECT_EQ(r.vertices_clamped, 0);
  // Half-way between the first two axes, the line passes half-way between its two values.
  const cv::Point2d a = r.ToPixel(0, 4.0), b = r.ToPixel(1, 13.0);
  const cv::Point mid(static_cast<int>(std::lround((a.x + b.x) / 2)), static_cast<int>(std::lround((a.y + b.y) / 2)));
  EXPECT_TRUE(HasColourNear(r.image, mid, 1, kVermillion));
  // The middle value of an axis sits half-way up it.
  EXPECT_NEAR(r.ToPixel(0, 4.0).y, (r.axis_top + r.axis_bottom) / 2.0, 0.51);
}

TEST(RenderParallelCoordinates, AValueBeyondItsAxisIsDrawnAtItsEndAndMarked) {
  ParallelCoordinatesOptions o;
  o.width = 900;
  o.height = 400;
  const ParallelLine beyond{{9.0, 13.0, 500.0}, kVermillion, 3, true};  // 9 m on a 2..6 m axis
  const RenderedParallel r = RenderParallelCoordinates(ThreeAxes(), {beyond}, {}, o);
  EXPECT_EQ(r.vertices_clamped, 1);
  EXPECT_EQ(r.ToPixel(0, 9.0).y, r.axis_top);
  // The triangle above the axis's top.
  const cv::Point above(r.axis_x[0], r.axis_top - 4 - o.marker_size / 2);
  EXPECT_TRUE(HasColourNear(r.image, above, 2, kVermillion));
  // Unmarked, the same line leaves no triangle there.
  ParallelLine plain = beyond;
  plain.mark_clamped = false;
  const RenderedParallel u = RenderParallelCoordinates(ThreeAxes(), {plain}, {}, o);
  EXPECT_EQ(u.vertices_clamped, 1);
  EXPECT_FALSE(HasColourNear(u.image, above, 2, kVermillion));
}

TEST(RenderParallelCoordinates, NonFiniteValuesBreakTheLine) {
  ParallelCoordinatesOptions o;
  o.width = 900;
  o.height = 400;
  const ParallelLine gap{{4.0, std::numeric_limits<double>::quiet_NaN(), 500.0}, kVermillion, 3, true};
  const RenderedParallel r = RenderParallelCoordinates(ThreeAxes(), {gap}, {}, o);
  const cv::Point2d a = r.ToPixel(0, 4.0);
  const cv::Point mid(static_cast<int>(std::lround((a.x + r.axis_x[1]) / 2)), static_cast<int>(std::lround(a.y)));
  EXPECT_FALSE(HasColourNear(r.image, mid, 1, kVermillion));
  EXPECT_EQ(r.vertices_clamped, 0);
}

TEST(RenderParallelCoordinates, RejectsBadOptionsAndLimits) {
  ParallelCoordinatesOptions o;
  o.width = 100;
  EXPECT_THROW(RenderParallelCoordinates(ThreeAxes(), {}, {}, o), InputError);
  auto axes = ThreeAxes();
  axes[1].limits = {5.0, 5.0};
  EXPECT_THROW(RenderParallelCoordinates(axes, {}, {}, ParallelCoordinatesOptions{}), InputError);
}

}  // namespace
}  // namespace slamtune::report
