#include "slamtune/slam/params/base_configuration.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::HasSubstr;

// A parameter file in the test's temporary folder.
std::string WriteFile(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(path) << text;
  return path.string();
}

const std::string kToolboxFile =
    "slam_toolbox:\n  ros__parameters:\n    loop_search_maximum_distance: 5.0\n    minimum_time_interval: 1.0\n";
const std::string kKartoFile = "loop_search_maximum_distance: 5.0\n";

TEST(BaseConfiguration, AFileGoesOverItsNodesDeclaredDefaultsWhateverThePreset) {
  const std::string toolbox = WriteFile("toolbox.yaml", kToolboxFile);
  const BaseConfiguration plain = LoadBaseConfiguration(toolbox, "", {});
  MapperParams expected = NodeDefaults(RosNode::kSlamToolbox);
  expected.loop_search_maximum_distance = 5.0;
  expected.sync_minimum_time_interval = 1.0;
  EXPECT_EQ(plain.params, expected);
  EXPECT_EQ(plain.node, RosNode::kSlamToolbox);
  EXPECT_EQ(plain.params.node_mode, NodeMode::kSlamToolboxAsync);
  EXPECT_EQ(plain.label, "your configuration (toolbox.yaml)");
  // --preset names only the mode.
  const BaseConfiguration sync = LoadBaseConfiguration(toolbox, "slam_toolbox_sync", {});
  expected.node_mode = NodeMode::kSlamToolboxSync;
  EXPECT_EQ(sync.params, expected);
  EXPECT_EQ(LoadBaseConfiguration(toolbox, "slam_toolbox_offline", {}).params.node_mode, NodeMode::kSlamToolboxOffline);
  // A flat file is slam_karto's, over open_karto's defaults (slam_karto's when it loads no file).
  const std::string karto = WriteFile("karto.yaml", kKartoFile);
  for (const char* preset : {"", "slam_karto", "open_karto"}) {
    const BaseConfiguration k = LoadBaseConfiguration(karto, preset, {});
    MapperParams e = NodeDefaults(RosNode::kSlamKarto);
    e.loop_search_maximum_distance = 5.0;
    EXPECT_EQ(k.params, e) << preset;
    EXPECT_EQ(k.node, RosNode::kSlamKarto);
  }
}

TEST(BaseConfiguration, APresetOfAnotherNodeThanTheFilesIsRefused) {
  const std::string toolbox = WriteFile("toolbox.yaml", kToolboxFile);
  EXPECT_THAT(ErrorMessageOf([&] { LoadBaseConfiguration(toolbox, "slam_karto", {}); }),
              HasSubstr("a slam_toolbox (ROS 2) parameter file, but --preset slam_karto is slam_karto's"));
  const std::string karto = WriteFile("karto.yaml", kKartoFile);
  EXPECT_THAT(ErrorMessageOf([&] { LoadBaseConfiguration(karto, "slam_toolbox_sync", {}); }),
              HasSubstr("a slam_karto (flat) parameter file, but --preset slam_toolbox_sync is slam_toolbox's"));
  EXPECT_THAT(ErrorMessageOf([&] { LoadBaseConfiguration("", "slam_toolbox_fast", {}); }),
              HasSubstr("unknown preset 'slam_toolbox_fast': must be slam_karto, open_karto, slam_toolbox, "
                        "slam_toolbox_sync or slam_toolbox_offline"));
}

TEST(BaseConfiguration, WithoutAFileThePresetThenSets) {
  const BaseConfiguration none = LoadBaseConfiguration("", "", {});
  EXPECT_EQ(none.params, MapperParams::Preset("slam_karto"));
  EXPECT_EQ(none.label, "slam_karto's defaults");
  const BaseConfiguration sync = LoadBaseConfiguration("", "slam_toolbox_sync", {"loop_search_maximum_distance=4"});
  MapperParams e = MapperParams::Preset("slam_toolbox_sync");
  e.loop_search_maximum_distance = 4;
  EXPECT_EQ(sync.params, e);
  EXPECT_EQ(sync.node, RosNode::kSlamToolbox);
  EXPECT_EQ(sync.label, "slam_toolbox_sync's defaults with --set");
}

TEST(BaseConfiguration, AFileOptimizeWroteRunsInTheModeItWasTunedFor) {
  const std::string tuned =
      WriteFile("best.yaml",
                "# slamtune optimize, tuned for slam_toolbox_sync (slam_toolbox online_sync_launch.py "
                "(synchronous node)): the recommendation ...\n" +
                    kToolboxFile);
  const BaseConfiguration b = LoadBaseConfiguration(tuned, "", {});
  EXPECT_EQ(b.params.node_mode, NodeMode::kSlamToolboxSync);
  EXPECT_EQ(b.mode_source, "best.yaml's first comment");
  // --preset wins.
  const BaseConfiguration a = LoadBaseConfiguration(tuned, "slam_toolbox", {});
  EXPECT_EQ(a.params.node_mode, NodeMode::kSlamToolboxAsync);
  EXPECT_EQ(a.mode_source, "--preset");
}

TEST(BaseConfiguration, OlderFoldersKeepThePresetUnderTheFile) {
  const std::string toolbox = WriteFile("toolbox.yaml", kToolboxFile);
  const BaseConfiguration old = LoadBaseConfiguration(toolbox, "slam_toolbox", {}, BaseRule::kPresetThenFile);
  MapperParams e = MapperParams::Preset("slam_toolbox");
  e.loop_search_maximum_distance = 5.0;
  e.sync_minimum_time_interval = 1.0;
  EXPECT_EQ(old.params, e);
  EXPECT_NE(old.params, LoadBaseConfiguration(toolbox, "slam_toolbox", {}).params);  // 0.5 vs 0.05 penalty floor
}

}  // namespace
}  // namespace slamtune::slam
