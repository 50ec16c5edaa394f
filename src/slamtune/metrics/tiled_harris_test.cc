#include "slamtune/metrics/tiled_harris.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <tuple>

#include "slamtune/metrics/synthetic_map.h"

namespace slamtune::metrics {
namespace {

// Blurred wall mask of rooms spread over several tiles, some rotated, some crossing tile edges.
cv::Mat SmoothedRooms() {
  io::MapImage map = DrawSyntheticRooms(
      400, 300, {{64, 64, 60, 40, 0}, {130, 120, 90, 70, 7}, {300, 200, 150, 110, -12}, {127.5, 255.5, 40, 30, 0}});
  cv::Mat grey(map.height, map.width, CV_8UC1, map.pixels.data());
  cv::Mat walls = grey == io::kMapOccupied, smoothed;
  cv::GaussianBlur(walls, smoothed, cv::Size(3, 3), 0);
  return smoothed;
}

// Largest |tiled - whole-image| as a fraction of the largest |whole-image response|.
double RelativeDifference(const cv::Mat& image, int block, int aperture, double k) {
  cv::Mat reference;
  cv::cornerHarris(image, reference, block, aperture, k);
  const double scale = cv::norm(reference, cv::NORM_INF);
  const double difference = cv::norm(TiledHarrisResponse(image, block, aperture, k).Dense(), reference, cv::NORM_INF);
  return scale > 0.0 ? difference / scale : difference;
}

constexpr double kRounding = 1e-6;  // a few float ulps of the largest response

class TiledHarrisTest : public ::testing::TestWithParam<std::tuple<int, int, double>> {};

TEST_P(TiledHarrisTest, EqualsWholeImageCornerHarrisOnWalls) {
  const auto [block, aperture, k] = GetParam();
  const cv::Mat image = SmoothedRooms();
  cv::Mat reference;
  cv::cornerHarris(image, reference, block, aperture, k);
  double max_response = 0.0;
  cv::minMaxLoc(reference, nullptr, &max_response);
  ASSERT_GT(max_response, 0.0);  // the comparison is not between two empty images
  EXPECT_LE(RelativeDifference(image, block, aperture, k), kRounding);
  // What the metric uses, corner pixels over 1 % of the largest response, is identical.
  const cv::Mat tiled = TiledHarrisResponse(image, block, aperture, k).Dense();
  EXPECT_EQ(cv::countNonZero((tiled > 0.01 * max_response) != (reference > 0.01 * max_response)), 0);
}

TEST_P(TiledHarrisTest, EqualsWholeImageCornerHarrisOnNoise) {
  const auto [block, aperture, k] = GetParam();
  cv::Mat noise(300, 290, CV_8UC1);
  cv::RNG rng(42);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  EXPECT_LE(RelativeDifference(noise, block, aperture, k), kRounding);
}

// What the map metric reads: the largest response and the mask above a threshold, on windows
// that cut through tiles, against the dense image.
TEST_P(TiledHarrisTest, MaxAndMaskOfAWindowEqualTheDenseImage) {
  const auto [block, aperture, k] = GetParam();
  const HarrisTiles tiles = TiledHarrisResponse(SmoothedRooms(), block, aperture, k);
  const cv::Mat dense = tiles.Dense();
  for (const cv::Rect window : {cv::Rect(0, 0, dense.cols, dense.rows), cv::Rect(37, 11, 250, 201),
                                cv::Rect(200, 150, 200, 150), cv::Rect(5, 5, 1, 1)}) {
    double expected_max = 0.0;
    cv::minMaxLoc(dense(window), nullptr, &expected_max);
    EXPECT_EQ(tiles.MaxIn(window), expected_max) << window;
    for (const double fraction : {0.01, 0.2}) {
      const double threshold = fraction * std::max(expected_max, 1.0);
      EXPECT_EQ(cv::countNonZero(tiles.Above(window, threshold) != (dense(window) > threshold)), 0) << window;
    }
  }
  // A window along an edge, inside one tile, where every response is negative: the maximum
  // is negative too (no uncovered pixel adds a 0).
  cv::Mat flat(kHarrisTileSize, kHarrisTileSize, CV_8UC1, cv::Scalar(0));
  cv::line(flat, {10, 64}, {118, 64}, cv::Scalar(255), 3);
  const HarrisTiles line = TiledHarrisResponse(flat, block, aperture, k);
  const cv::Rect edge(20, 62, 80, 1);
  double line_max = 0.0;
  cv::minMaxLoc(line.Dense()(edge), nullptr, &line_max);
  ASSERT_LT(line_max, 0.0);
  EXPECT_EQ(line.MaxIn(edge), line_max);
}

INSTANTIATE_TEST_SUITE_P(Options, TiledHarrisTest,
                         ::testing::Values(std::make_tuple(2, 3, 0.04), std::make_tuple(3, 5, 0.06),
                                           std::make_tuple(2, 1, 0.04), std::make_tuple(5, 7, 0.1)));

TEST(TiledHarrisSmallTest, ImageSmallerThanATileAndEmptyImage) {
  cv::Mat small = cv::Mat::zeros(20, 30, CV_8UC1);
  cv::rectangle(small, cv::Rect(5, 5, 10, 8), cv::Scalar(255));
  EXPECT_LE(RelativeDifference(small, 2, 3, 0.04), kRounding);
  const cv::Mat empty = cv::Mat::zeros(kHarrisTileSize * 2 + 3, kHarrisTileSize + 1, CV_8UC1);
  const HarrisTiles none = TiledHarrisResponse(empty, 2, 3, 0.04);
  EXPECT_TRUE(none.tiles.empty());
  EXPECT_EQ(cv::countNonZero(none.Dense()), 0);
  EXPECT_EQ(none.MaxIn(cv::Rect(0, 0, empty.cols, empty.rows)), 0.0);
}

}  // namespace
}  // namespace slamtune::metrics
