#include "slamtune/metrics/map_quality.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/metrics/synthetic_map.h"

namespace slamtune::metrics {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// One 40 x 30 room (outer size) in the middle of a 100 x 80 map.
constexpr SyntheticRoom kRoom{49.5, 39.5, 40, 30, 0.0};

io::MapImage SingleRoom() { return DrawSyntheticRooms(100, 80, {kRoom}); }

SyntheticRoom Rotated(SyntheticRoom room, double angle_deg) {
  room.angle_deg = angle_deg;
  return room;
}

void ExpectSameFigures(const MapQuality& a, const MapQuality& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.occupied_cells, b.occupied_cells);
  EXPECT_EQ(a.free_cells, b.free_cells);
  EXPECT_EQ(a.occupied_ratio, b.occupied_ratio);
  EXPECT_EQ(a.max_corner_response, b.max_corner_response);
  EXPECT_EQ(a.corner_pixels, b.corner_pixels);
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.enclosed_areas, b.enclosed_areas);
  EXPECT_EQ(a.contours, b.contours);
}

TEST(MapQualityTest, AllUnknownMapHasNothing) {
  const MapQuality q = ComputeMapQuality(DrawSyntheticRooms(60, 40, {}));
  EXPECT_EQ(q.width, 60);
  EXPECT_EQ(q.height, 40);
  EXPECT_EQ(q.unknown_cells, 2400);
  EXPECT_EQ(q.occupied_ratio, 0.0);
  EXPECT_EQ(q.occupied_ratio_known, 0.0);
  EXPECT_EQ(q.corner_pixels, 0);
  EXPECT_EQ(q.corners, 0);
  EXPECT_EQ(q.enclosed_areas, 0);
  EXPECT_EQ(q.contours, 0);
  EXPECT_THAT(q.message, HasSubstr("no occupied cells"));
}

TEST(MapQualityTest, SingleRoomHasOneEnclosedAreaAndFourCorners) {
  const MapQuality q = ComputeMapQuality(SingleRoom());
  // Walls: the 40 x 30 outline = 2 * 40 + 2 * 30 - 4 cells; inside 38 x 28 free cells.
  EXPECT_EQ(q.occupied_cells, 136);
  EXPECT_EQ(q.free_cells, 38 * 28);
  EXPECT_DOUBLE_EQ(q.occupied_ratio, 136.0 / 8000.0);
  EXPECT_DOUBLE_EQ(q.occupied_ratio_known, 136.0 / (136.0 + 38 * 28));
  EXPECT_EQ(q.enclosed_areas, 1);
  EXPECT_EQ(q.contours, 2);  // outer border of the wall + its hole
  EXPECT_EQ(q.corners, 4);
  // A few pixels at each corner.
  EXPECT_GE(q.corner_pixels, 4);
  EXPECT_LE(q.corner_pixels, 4 * 16);
  EXPECT_GT(q.max_corner_response, 0.0);
}

TEST(MapQualityTest, NestedRoomsAreTwoEnclosedAreas) {
  const MapQuality q = ComputeMapQuality(DrawSyntheticRooms(100, 80, {kRoom, {49.5, 39.5, 16, 12, 0.0}}));
  EXPECT_EQ(q.enclosed_areas, 2);
  EXPECT_EQ(q.contours, 4);
  EXPECT_EQ(q.corners, 8);
}

TEST(MapQualityTest, RoomDrawnTwiceWithSmallRotationScoresWorseOnAllThree) {
  const MapQuality single = ComputeMapQuality(SingleRoom());
  // 5 degrees about the centre moves the corners by ~2 cells: the outlines cross and leave
  // slivers of free cells between them (at 3 degrees the slivers hold no free cell yet).
  const MapQuality doubled = ComputeMapQuality(DrawSyntheticRooms(100, 80, {kRoom, Rotated(kRoom, 5.0)}));
  EXPECT_GT(doubled.occupied_ratio, single.occupied_ratio);
  EXPECT_GT(doubled.corner_pixels, single.corner_pixels);
  EXPECT_GT(doubled.enclosed_areas, single.enclosed_areas);
}

TEST(MapQualityTest, OneCellGapOpensTheRoom) {
  io::MapImage map = SingleRoom();
  // Top wall is row 25 (centre 39.5 - 14.5), columns 30..69; open its middle cell.
  ASSERT_EQ(map.at(49, 25), io::kMapOccupied);
  map.pixels[25 * map.width + 49] = io::kMapFree;
  const MapQuality q = ComputeMapQuality(map);
  EXPECT_EQ(q.enclosed_areas, 0);
  EXPECT_EQ(q.contours, 1);
  EXPECT_EQ(q.occupied_cells, 135);
  // The two wall ends at the gap respond like corners.
  EXPECT_GT(q.corner_pixels, ComputeMapQuality(SingleRoom()).corner_pixels);
}

TEST(MapQualityTest, WallsOnTheImageBorderStillEncloseTheRoom) {
  // The room's outline is the image's outermost ring of cells.
  const MapQuality q = ComputeMapQuality(DrawSyntheticRooms(40, 30, {{19.5, 14.5, 40, 30, 0.0}}));
  EXPECT_EQ(q.occupied_cells, 136);
  EXPECT_EQ(q.enclosed_areas, 1);
  EXPECT_EQ(q.corners, 4);
}

TEST(MapQualityTest, UnknownSurroundingsChangeOnlyEta) {
  // The same room in a map 5x larger, off-centre: corners and enclosed areas must not move.
  const MapQuality small = ComputeMapQuality(SingleRoom());
  const MapQuality large = ComputeMapQuality(DrawSyntheticRooms(500, 400, {{137.5, 301.5, 40, 30, 0.0}}));
  EXPECT_EQ(large.occupied_cells, small.occupied_cells);
  EXPECT_DOUBLE_EQ(large.occupied_ratio, small.occupied_ratio / 25.0);
  EXPECT_EQ(large.max_corner_response, small.max_corner_response);
  EXPECT_EQ(large.corner_pixels, small.corner_pixels);
  EXPECT_EQ(large.corners, small.corners);
  EXPECT_EQ(large.enclosed_areas, small.enclosed_areas);
}

TEST(MapQualityTest, UsesTheMapsOwnGreyRule) {
  // The single room stored negated (occupied 255, free 0, unknown 128) scores the same.
  io::MapImage trinary = SingleRoom();
  io::MapImage negated = trinary;
  negated.negate = true;
  for (auto& v : negated.pixels) v = v == io::kMapOccupied ? 255 : v == io::kMapFree ? 0 : 128;
  ExpectSameFigures(ComputeMapQuality(negated), ComputeMapQuality(trinary));
}

TEST(MapQualityTest, CornerClustersAreEightConnectedComponents) {
  const io::MapImage map =
      DrawSyntheticRooms(300, 200, {kRoom, Rotated(kRoom, 5.0), {150, 100, 80, 60, 17.0}, {200, 60, 50, 50, 33.0}});
  const MapQualityDetail detail = AnalyseMapQuality(map);
  cv::Mat labels;
  const int components = cv::connectedComponents(detail.corner_mask, labels, 8, CV_32S) - 1;
  EXPECT_GT(components, 8);
  EXPECT_EQ(detail.quality.corners, components);
  EXPECT_EQ(detail.quality.corner_pixels, cv::countNonZero(detail.corner_mask));
}

TEST(MapQualityTest, IsDeterministic) {
  const io::MapImage map = DrawSyntheticRooms(300, 200, {kRoom, Rotated(kRoom, 2.0), {150, 100, 80, 60, 17.0}});
  ExpectSameFigures(ComputeMapQuality(map), ComputeMapQuality(map));
}

TEST(MapQualityTest, PgmAndPngGiveTheSameNumbers) {
  const fs::path dir = fs::temp_directory_path() / ("slamtune_map_quality_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const io::MapImage map = DrawSyntheticRooms(100, 80, {kRoom, Rotated(kRoom, 3.0)});
  io::WriteMapServer(map, (dir / "m.yaml").string());
  io::WritePng(map, (dir / "m.png").string());
  const MapQuality from_yaml = ComputeMapQuality(io::ReadMap((dir / "m.yaml").string()));
  const MapQuality from_pgm = ComputeMapQuality(io::ReadMap((dir / "m.pgm").string()));
  const MapQuality from_png = ComputeMapQuality(io::ReadMap((dir / "m.png").string()));
  fs::remove_all(dir);
  const MapQuality in_memory = ComputeMapQuality(map);
  ExpectSameFigures(from_yaml, in_memory);
  ExpectSameFigures(from_pgm, in_memory);
  ExpectSameFigures(from_png, in_memory);
}

TEST(MapQualityTest, OptionsChangeTheCornerCount) {
  MapQualityOptions strict;
  strict.corner_threshold = 0.5;  // only the strongest responses
  const io::MapImage map = SingleRoom();
  EXPECT_LT(ComputeMapQuality(map, strict).corner_pixels, ComputeMapQuality(map).corner_pixels);
  MapQualityOptions no_blur;
  no_blur.blur_size = 1;
  EXPECT_EQ(ComputeMapQuality(map, no_blur).corners, 4);
}

TEST(MapQualityOptionsTest, ValidateNamesFieldValueAndRule) {
  EXPECT_NO_THROW(MapQualityOptions{}.Validate());
  MapQualityOptions o;
  o.blur_size = 4;
  EXPECT_EQ(slamtune::testing::ErrorMessageOf([&] { o.Validate(); }),
            "map quality option blur_size = 4: must be odd and in [1, 31] pixels");
  o = {};
  o.blur_size = -1;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("blur_size = -1")));
  o = {};
  o.blur_sigma = -0.5;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("blur_sigma = -0.5: must be >= 0")));
  o = {};
  o.harris_block_size = 1;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("harris_block_size = 1: must be in [2, 31]")));
  o = {};
  o.harris_aperture = 2;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("harris_aperture = 2: must be 1, 3, 5 or 7")));
  o = {};
  o.harris_k = 0.0;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("harris_k = 0: must be in (0, 0.25)")));
  o = {};
  o.corner_threshold = 1.5;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("corner_threshold = 1.5: must be in (0, 1]")));
  o = {};
  o.corner_threshold = 0.0;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("corner_threshold = 0")));
}

TEST(MapQualityTest, RejectsMalformedMapsAndOptionsBeforeWork) {
  io::MapImage empty;
  EXPECT_THROW(ComputeMapQuality(empty), InputError);
  try {
    ComputeMapQuality(empty);
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("empty map (0 x 0 cells)"));
  }
  MapQualityOptions bad;
  bad.harris_aperture = 4;
  EXPECT_THROW(ComputeMapQuality(SingleRoom(), bad), InputError);
}

TEST(SyntheticMapTest, RejectsDegenerateInput) {
  EXPECT_THROW(DrawSyntheticRooms(0, 10, {}), InputError);
  EXPECT_THROW(DrawSyntheticRooms(10, 10, {{5, 5, 2, 5, 0}}), InputError);
}

}  // namespace
}  // namespace slamtune::metrics
