#include "slamtune/tune/map_evaluation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/map_image.h"

namespace slamtune::tune {
namespace {

// A 60 x 40 free room with a one-cell wall around it.
io::MapImage Room() {
  io::MapImage m = io::UniformMap(60, 40, io::kMapFree);
  for (int c = 0; c < 60; ++c) m.pixels[c] = m.pixels[39 * 60 + c] = 0;
  for (int r = 0; r < 40; ++r) m.pixels[r * 60] = m.pixels[r * 60 + 59] = 0;
  return m;
}

TEST(EvaluateMaps, EachMapIsMeasuredAndOverlaysOfTheSameStemDoNotClash) {
  const std::filesystem::path dir = testing::UniqueTempDir("map_evaluation");
  std::filesystem::create_directories(dir / "a");
  std::filesystem::create_directories(dir / "b");
  io::WriteMapServer(Room(), (dir / "a" / "map.yaml").string());
  io::WriteMapServer(Room(), (dir / "b" / "map.yaml").string());
  const std::vector<std::string> maps = {(dir / "a" / "map.yaml").string(), (dir / "b" / "map.yaml").string()};
  const std::vector<MapEvaluation> plain = EvaluateMaps(maps, {}, "");
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain[0].quality.occupied_cells, 2 * 60 + 2 * 38);
  EXPECT_EQ(plain[0].quality.enclosed_areas, plain[1].quality.enclosed_areas);
  EXPECT_TRUE(plain[0].overlay.empty());

  const std::vector<MapEvaluation> drawn = EvaluateMaps(maps, {}, (dir / "overlays").string());
  EXPECT_EQ(std::filesystem::path(drawn[0].overlay).filename(), "map.quality.png");
  EXPECT_EQ(std::filesystem::path(drawn[1].overlay).filename(), "2_map.quality.png");
  EXPECT_TRUE(std::filesystem::exists(drawn[1].overlay));
  EXPECT_EQ(ToJson(drawn[1]).at("overlay"), drawn[1].overlay);
  EXPECT_EQ(ToJson(plain[0]).at("occupied_cells"), plain[0].quality.occupied_cells);
  std::filesystem::remove_all(dir);
}

TEST(EvaluateMaps, BadOptionsAreRefusedBeforeAnyFileIsRead) {
  metrics::MapQualityOptions o;
  o.harris_k = 0.5;
  EXPECT_THAT([&] { EvaluateMaps({"/nonexistent/map.yaml"}, o, ""); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("harris_k")));
  EXPECT_THAT([] { EvaluateMaps({"/nonexistent/map.yaml"}, {}, ""); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("/nonexistent/map.yaml")));
}

}  // namespace
}  // namespace slamtune::tune
