#include "slamtune/metrics/map_quality_overlay.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "slamtune/common/error.h"
#include "slamtune/metrics/synthetic_map.h"

namespace slamtune::metrics {
namespace {

// 100 x 80 map, one 40 x 30 room: columns 30..69, rows 25..54.
io::MapImage Room() { return DrawSyntheticRooms(100, 80, {{49.5, 39.5, 40, 30, 0.0}}); }

cv::Vec3b At(const cv::Mat& overlay, int scale, int col, int row) {
  return overlay.at<cv::Vec3b>(22 + row * scale + scale / 2, col * scale + scale / 2);  // below the caption
}

TEST(MapQualityOverlayTest, ShowsWallsAreasCornersAndUnknown) {
  const io::MapImage map = Room();
  const MapQualityDetail detail = AnalyseMapQuality(map);
  const cv::Mat overlay = RenderMapQualityOverlay(map, detail);
  const int scale = 4;  // 480 / 100
  ASSERT_EQ(overlay.type(), CV_8UC3);
  EXPECT_EQ(overlay.cols, 100 * scale);
  EXPECT_EQ(overlay.rows, 80 * scale + 22);
  EXPECT_EQ(At(overlay, scale, 5, 5), cv::Vec3b(170, 170, 170));    // unknown
  EXPECT_EQ(At(overlay, scale, 49, 25), cv::Vec3b(0, 0, 0));        // middle of the top wall
  EXPECT_EQ(At(overlay, scale, 49, 39), cv::Vec3b(230, 180, 120));  // the enclosed area's colour
  EXPECT_EQ(At(overlay, scale, 30, 25), cv::Vec3b(0, 0, 230));      // a corner cell is red
  cv::Mat red;
  cv::inRange(overlay, cv::Scalar(0, 0, 230), cv::Scalar(0, 0, 230), red);
  EXPECT_GE(cv::countNonZero(red), detail.quality.corner_pixels * scale * scale);
}

TEST(MapQualityOverlayTest, WritesPngAndReturnsTheFigures) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("slamtune_overlay_" + std::to_string(::getpid()) + ".png")).string();
  const io::MapImage map = Room();
  const MapQuality q = WriteMapQualityOverlay(map, {}, path);
  const cv::Mat back = cv::imread(path, cv::IMREAD_UNCHANGED);
  std::filesystem::remove(path);
  EXPECT_EQ(back.channels(), 3);
  EXPECT_EQ(back.cols, 400);
  EXPECT_EQ(q.corner_pixels, ComputeMapQuality(map).corner_pixels);
  EXPECT_EQ(q.enclosed_areas, 1);
}

TEST(MapQualityOverlayTest, RejectsBadPaths) {
  EXPECT_THROW(WriteMapQualityOverlay(Room(), {}, "/tmp/overlay.jpg"), InputError);
  try {
    WriteMapQualityOverlay(Room(), {}, "/nonexistent-dir/overlay.png");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("/nonexistent-dir/overlay.png: cannot write the overlay"));
  }
}

}  // namespace
}  // namespace slamtune::metrics
