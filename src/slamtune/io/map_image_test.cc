#include "slamtune/io/map_image.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::io {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A 6 x 4 trinary map with every class present and an asymmetric layout (catches flips).
MapImage SmallMap() {
  MapImage map;
  map.width = 6;
  map.height = 4;
  map.resolution = 0.025;
  map.origin = Pose2{-12.345678901234, 3.3, 0.7};
  map.pixels = {kMapOccupied, kMapOccupied, kMapFree,     kMapFree,     kMapUnknown, kMapUnknown,
                kMapFree,     kMapFree,     kMapFree,     kMapOccupied, kMapUnknown, kMapUnknown,
                kMapUnknown,  kMapFree,     kMapOccupied, kMapFree,     kMapFree,    kMapUnknown,
                kMapUnknown,  kMapUnknown,  kMapUnknown,  kMapUnknown,  kMapFree,    kMapOccupied};
  return map;
}

class MapImageFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("slamtune_map_image_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::string WriteText(const std::string& name, const std::string& text) const {
    std::ofstream(Path(name), std::ios::binary) << text;
    return Path(name);
  }

  fs::path dir_;
};

TEST(UniformMap, EveryCellHasTheGreyValueAtTheDefaultGeometry) {
  const MapImage map = UniformMap(7, 3, kMapUnknown);
  EXPECT_EQ(map.width, 7);
  EXPECT_EQ(map.height, 3);
  EXPECT_EQ(map.pixels, std::vector<std::uint8_t>(21, kMapUnknown));
  EXPECT_EQ(map.resolution, kDefaultResolution);
  EXPECT_EQ(map.origin.x, 0.0);
  EXPECT_EQ(map.origin.y, 0.0);
  EXPECT_NO_THROW(ValidateMapImage(map, "map"));
}

TEST(ClassifyGreyTest, FollowsMapServerRule) {
  EXPECT_EQ(ClassifyGrey(0, false, 0.65, 0.196), CellClass::kOccupied);
  EXPECT_EQ(ClassifyGrey(254, false, 0.65, 0.196), CellClass::kFree);
  EXPECT_EQ(ClassifyGrey(255, false, 0.65, 0.196), CellClass::kFree);
  // 205 -> p = 50/255 = 0.19608, just above free_thresh 0.196: unknown (why ROS1 uses 0.196).
  EXPECT_EQ(ClassifyGrey(205, false, 0.65, 0.196), CellClass::kUnknown);
  // Around occupied_thresh: v = 89 -> p = 166/255 = 0.651 (occupied), v = 90 -> p = 0.647.
  EXPECT_EQ(ClassifyGrey(89, false, 0.65, 0.196), CellClass::kOccupied);
  EXPECT_EQ(ClassifyGrey(90, false, 0.65, 0.196), CellClass::kUnknown);
  // Strictly greater: p == occupied_thresh is not occupied.
  EXPECT_EQ(ClassifyGrey(0, false, 1.0, 0.196), CellClass::kUnknown);
  EXPECT_EQ(ClassifyGrey(255, true, 0.65, 0.196), CellClass::kOccupied);
  EXPECT_EQ(ClassifyGrey(0, true, 0.65, 0.196), CellClass::kFree);
  EXPECT_EQ(ClassifyGrey(100, true, 0.65, 0.196), CellClass::kUnknown);
}

TEST_F(MapImageFileTest, MapServerRoundTripKeepsPixelsResolutionAndOrigin) {
  const MapImage map = SmallMap();
  WriteMapServer(map, Path("round.yaml"));
  ASSERT_TRUE(fs::exists(Path("round.pgm")));
  std::ifstream pgm(Path("round.pgm"), std::ios::binary);
  std::string magic(2, '\0');
  pgm.read(magic.data(), 2);
  EXPECT_EQ(magic, "P5");
  std::ifstream yaml(Path("round.yaml"));
  const std::string text((std::istreambuf_iterator<char>(yaml)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("image: round.pgm"));  // relative name
  EXPECT_THAT(text, HasSubstr("negate: 0"));

  const MapImage back = ReadMap(Path("round.yaml"));
  EXPECT_EQ(back.width, map.width);
  EXPECT_EQ(back.height, map.height);
  EXPECT_EQ(back.pixels, map.pixels);
  EXPECT_EQ(back.resolution, map.resolution);
  EXPECT_EQ(back.origin, map.origin);
  EXPECT_FALSE(back.negate);
}

TEST_F(MapImageFileTest, PngRoundTripKeepsPixelsWithDefaultGeometry) {
  const MapImage map = SmallMap();
  WritePng(map, Path("map.png"));
  const MapImage back = ReadMap(Path("map.png"));
  EXPECT_EQ(back.pixels, map.pixels);
  EXPECT_EQ(back.resolution, 0.05);
  EXPECT_EQ(back.origin, Pose2{});
}

TEST_F(MapImageFileTest, ForeignGreyLevelsAreClassifiedToTrinary) {
  // Grey values as another SLAM system might save them: dark = occupied, light = free.
  cv::Mat grey(1, 5, CV_8UC1);
  const std::uint8_t values[] = {10, 80, 128, 210, 250};
  for (int i = 0; i < 5; ++i) grey.at<std::uint8_t>(0, i) = values[i];
  ASSERT_TRUE(cv::imwrite(Path("foreign.pgm"), grey));
  const MapImage map = ReadMap(Path("foreign.pgm"));
  const std::vector<std::uint8_t> expected = {kMapOccupied, kMapOccupied, kMapUnknown, kMapFree, kMapFree};
  EXPECT_EQ(map.pixels, expected);
}

TEST_F(MapImageFileTest, NegatedYamlGivesTheSameMap) {
  const MapImage map = SmallMap();
  // Negated encoding: occupied = 255, free = 0, unknown = 128 (p = 0.502).
  cv::Mat grey(map.height, map.width, CV_8UC1);
  for (int r = 0; r < map.height; ++r) {
    for (int c = 0; c < map.width; ++c) {
      const std::uint8_t v = map.at(c, r);
      grey.at<std::uint8_t>(r, c) = v == kMapOccupied ? 255 : v == kMapFree ? 0 : 128;
    }
  }
  fs::create_directories(dir_ / "img");
  ASSERT_TRUE(cv::imwrite(Path("img/neg.png"), grey));
  WriteText("neg.yaml",
            "image: img/neg.png\nresolution: 0.025\norigin: [1.5, -2, 0]\nnegate: 1\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const MapImage back = ReadMap(Path("neg.yaml"));
  EXPECT_EQ(back.pixels, map.pixels);
  EXPECT_FALSE(back.negate);  // pixels are now plain trinary
  EXPECT_EQ(back.origin, (Pose2{1.5, -2.0, 0.0}));
  // The same image read without negate flips occupied and free.
  const MapImage plain = ReadMap(Path("img/neg.png"));
  EXPECT_EQ(plain.pixels[0], kMapFree);
}

TEST_F(MapImageFileTest, BadInputsNameTheFileAndTheProblem) {
  EXPECT_THAT([&] { ReadMap(Path("nope.pgm")); },
              ThrowsMessage<InputError>(HasSubstr("nope.pgm: cannot open map image: no such file")));
  EXPECT_THAT([&] { ReadMap(dir_.string()); }, ThrowsMessage<InputError>(HasSubstr("is a directory")));
  EXPECT_THAT([&] { ReadMap(WriteText("notes.pgm", "hello, I am text\n")); },
              ThrowsMessage<InputError>(HasSubstr("notes.pgm: not an image")));
  EXPECT_THAT(
      [&] { ReadMap(WriteText("zero.pgm", std::string("P5\n0 0\n255\n"))); },
      ThrowsMessage<InputError>(HasSubstr("zero.pgm: cannot decode the image: truncated, corrupt or empty (0 x 0)")));

  ASSERT_TRUE(cv::imwrite(Path("colour.png"), cv::Mat(4, 4, CV_8UC3, cv::Scalar(10, 200, 30))));
  EXPECT_THAT(
      [&] { ReadMap(Path("colour.png")); },
      ThrowsMessage<InputError>(HasSubstr("colour.png: is a 3-channel 8-bit image; maps must be 8-bit greyscale")));
  ASSERT_TRUE(cv::imwrite(Path("deep.png"), cv::Mat(4, 4, CV_16UC1, cv::Scalar(1000))));
  EXPECT_THAT([&] { ReadMap(Path("deep.png")); },
              ThrowsMessage<InputError>(HasSubstr("deep.png: is a 1-channel 16-bit image")));
}

TEST_F(MapImageFileTest, BadYamlNamesTheKey) {
  ASSERT_TRUE(cv::imwrite(Path("ok.pgm"), cv::Mat(3, 3, CV_8UC1, cv::Scalar(254))));
  const std::string tail = "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  EXPECT_THAT([&] { ReadMap(WriteText("a.yaml", "resolution: 0.05\norigin: [0, 0, 0]\n" + tail)); },
              ThrowsMessage<InputError>(HasSubstr("a.yaml: missing required key 'image'")));
  EXPECT_THAT([&] { ReadMap(WriteText("b.yaml", "image: ok.pgm\norigin: [0, 0, 0]\n" + tail)); },
              ThrowsMessage<InputError>(HasSubstr("b.yaml: missing required key 'resolution'")));
  EXPECT_THAT([&] { ReadMap(WriteText("c.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n")); },
              ThrowsMessage<InputError>(HasSubstr("c.yaml: missing required key 'occupied_thresh'")));
  EXPECT_THAT([&] { ReadMap(WriteText("d.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0]\n" + tail)); },
              ThrowsMessage<InputError>(HasSubstr("d.yaml:3: key 'origin' must be a list of 3 numbers")));
  EXPECT_THAT([&] { ReadMap(WriteText("e.yaml", "image: ok.pgm\nresolution: fine\norigin: [0, 0, 0]\n" + tail)); },
              ThrowsMessage<InputError>(HasSubstr("e.yaml:2: key 'resolution' must be a number")));
  EXPECT_THAT([&] { ReadMap(WriteText("f.yaml", "image: ok.pgm\nresolution: -1\norigin: [0, 0, 0]\n" + tail)); },
              ThrowsMessage<InputError>(HasSubstr("f.yaml: resolution = -1 m/cell; must be finite and > 0")));
  EXPECT_THAT([&] { ReadMap(WriteText("g.yaml", "image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n" + tail)); },
              ThrowsMessage<InputError>(
                  HasSubstr("gone.pgm: cannot open map image (named by " + Path("g.yaml") + "): no such file")));
  EXPECT_THAT([&] { ReadMap(WriteText("h.yaml", "image: ok.pgm\nresolution: [0.05\n")); },
              ThrowsMessage<InputError>(HasSubstr("h.yaml:3: invalid YAML")));
  EXPECT_THAT(
      [&] { ReadMap(WriteText("i.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 2\n" + tail)); },
      ThrowsMessage<InputError>(HasSubstr("i.yaml:4: key 'negate' must be 0 or 1")));
  EXPECT_THAT(
      [&] { ReadMap(WriteText("j.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nmode: raw\n" + tail)); },
      ThrowsMessage<InputError>(HasSubstr("only 'trinary' and 'scale'")));
  EXPECT_THAT(
      [&] {
        ReadMap(WriteText("k.yaml",
                          "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                          "occupied_thresh: 0.2\nfree_thresh: 0.5\n"));
      },
      ThrowsMessage<InputError>(HasSubstr("k.yaml: free_thresh = 0.5 > occupied_thresh = 0.2")));
  EXPECT_THAT([&] { ReadMap(WriteText("l.yaml", "- just\n- a list\n")); },
              ThrowsMessage<InputError>(HasSubstr("l.yaml: not a map_server YAML")));
  // The good file does read.
  EXPECT_EQ(ReadMap(WriteText("ok.yaml", "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n" + tail)).width, 3);
}

TEST_F(MapImageFileTest, WritersRejectEmptyMapsAndBadPaths) {
  const MapImage empty;
  try {
    WriteMapServer(empty, Path("empty.yaml"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("empty.yaml: empty map (0 x 0 cells)"));
  }
  EXPECT_FALSE(fs::exists(Path("empty.pgm")));
  try {
    WriteMapServer(SmallMap(), Path("map.pgm"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("must end in .yaml or .yml"));
  }
  try {
    WritePng(SmallMap(), Path("missing_dir/map.png"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing_dir/map.png: cannot write"));
  }
  MapImage short_pixels = SmallMap();
  short_pixels.pixels.pop_back();
  try {
    WritePng(short_pixels, Path("short.png"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("map has 23 pixels but width x height = 6 x 4 = 24"));
  }
}

// Runs `write` with files limited to `bytes` (SIGXFSZ ignored, so a write past it fails with
// EFBIG as on a full disk) and returns the error it threw, "" if none.
template <typename Write>
std::string ErrorWithFileLimit(rlim_t bytes, Write write) {
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  rlimit limited = old;
  limited.rlim_cur = bytes;
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  setrlimit(RLIMIT_FSIZE, &limited);
  std::string what;
  try {
    write();
  } catch (const InputError& e) {
    what = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  return what;
}

TEST_F(MapImageFileTest, AFullDiskNamesTheMapFileAndLeavesNoPartOfIt) {
  MapImage map = SmallMap();
  map.width = 200;
  map.height = 100;
  map.pixels.assign(20000, kMapFree);
  EXPECT_EQ(ErrorWithFileLimit(4096, [&] { WriteMapServer(map, Path("map.yaml")); }),
            Path("map.pgm") + ": cannot write (File too large)");
  EXPECT_FALSE(fs::exists(Path("map.pgm")));
  EXPECT_FALSE(fs::exists(Path("map.pgm.partial")));
  EXPECT_FALSE(fs::exists(Path("map.yaml")));  // never names a PGM that is not there
  cv::Mat noise(300, 300, CV_8UC1);
  cv::randu(noise, 0, 255);
  map.width = map.height = 300;
  map.pixels.assign(noise.data, noise.data + 90000);
  EXPECT_EQ(ErrorWithFileLimit(4096, [&] { WritePng(map, Path("map.png")); }),
            Path("map.png") + ": cannot write (File too large)");
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(MapImageFileTest, TruncatedImagesAreOneErrorWithNothingPrinted) {
  WriteMapServer(SmallMap(), Path("map.yaml"));
  WritePng(SmallMap(), Path("map.png"));
  for (const std::string name : {"map.pgm", "map.png"}) {
    std::ifstream in(Path(name), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    WriteText("cut_" + name, bytes.substr(0, bytes.size() - 10));
    ::testing::internal::CaptureStderr();
    const std::string error = slamtune::testing::ErrorMessageOf([&] { ReadMap(Path("cut_" + name)); });
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << name;
    EXPECT_THAT(error, HasSubstr(Path("cut_" + name) + ": ")) << name;
  }
  EXPECT_EQ(slamtune::testing::ErrorMessageOf([&] { ReadMap(WriteText("huge.pgm", "P5\n70000 70000\n255\n\x01")); }),
            Path("huge.pgm") + ": declares 70000 x 70000 pixels, more than the 1073741824 an image may have");
}

TEST_F(MapImageFileTest, MapYamlWithAByteOrderMarkAndADirectoryAsImage) {
  WriteMapServer(SmallMap(), Path("map.yaml"));
  std::ifstream in(Path("map.yaml"));
  const std::string yaml((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(ReadMap(WriteText("bom.yaml", "\xEF\xBB\xBF" + yaml)).pixels, SmallMap().pixels);
  fs::create_directories(Path("d.yaml"));
  EXPECT_THAT([&] { ReadMap(Path("d.yaml")); },
              ThrowsMessage<InputError>(HasSubstr("d.yaml: cannot open map YAML: is a directory")));
}

}  // namespace
}  // namespace slamtune::io
