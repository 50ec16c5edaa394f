#include "slamtune/tune/params_inspection.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"

namespace slamtune::tune {
namespace {

const std::string kToolbox = std::string(SLAMTUNE_SOURCE_DIR) + "/tests/fixtures/params/slam_toolbox_online_async.yaml";

class ParamsInspectionTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::UniqueTempDir("params_inspection"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Write(const char* name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  std::filesystem::path dir_;
};

TEST_F(ParamsInspectionTest, FilesStackInOrderAndSetsComeLast) {
  const std::string change = Write("change.yaml",
                                   "slam_toolbox:\n  ros__parameters:\n    loop_search_maximum_distance: 6.5\n"
                                   "    minimum_travel_distance: 0.3\n");
  const ParamsInspection i = InspectParamsFiles({kToolbox, change}, "", {"minimum_travel_distance=0.4"});
  ASSERT_EQ(i.files.size(), 2u);
  EXPECT_EQ(i.files[0].node, slam::RosNode::kSlamToolbox);
  EXPECT_TRUE(i.AllLoad());
  EXPECT_EQ(i.params.loop_search_maximum_distance, 6.5);
  EXPECT_EQ(i.params.minimum_travel_distance, 0.4);
  EXPECT_EQ(i.files[1].report.keys.size(), 2u);
  const nlohmann::ordered_json j = ToJson(i, false);
  EXPECT_EQ(j.at("params").at("loop_search_maximum_distance"), 6.5);
  EXPECT_EQ(j.at("files").size(), 2u);
  EXPECT_GT(ToJson(i, true).at("params").size(), j.at("params").size());  // all, not only what differs
}

TEST_F(ParamsInspectionTest, AFileTheNodeWouldNotTakeIsReportedNotRefused) {
  // An integer where the node declares a double: the engine reads it, the node would not.
  const std::string odd = Write("odd.yaml", "slam_toolbox:\n  ros__parameters:\n    loop_search_maximum_distance: 6\n");
  const ParamsInspection i = InspectParamsFiles({odd}, "", {});
  EXPECT_FALSE(i.AllLoad());
  ASSERT_FALSE(i.files[0].problems.empty());
  EXPECT_EQ(ToJson(i, false).at("files")[0].at("loads"), false);
}

TEST_F(ParamsInspectionTest, AnUnreadableValueOrFileIsRefused) {
  const std::string bad =
      Write("bad.yaml", "slam_toolbox:\n  ros__parameters:\n    loop_search_maximum_distance: far\n");
  EXPECT_THAT([&] { InspectParamsFiles({bad}, "", {}); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("bad.yaml")));
  EXPECT_THROW(InspectParamsFiles({(dir_ / "missing.yaml").string()}, "", {}), InputError);
}

TEST_F(ParamsInspectionTest, ListedParamsAreThoseThatDifferOrAllWithTheirValuesAsText) {
  const ParamsInspection i =
      InspectParamsFiles({kToolbox}, "", {"loop_search_maximum_distance=6.5", "do_loop_closing=false"});
  const auto find = [](const std::vector<ListedParam>& list, const std::string& name) -> const ListedParam* {
    for (const ListedParam& p : list) {
      if (p.name == name) return &p;
    }
    return nullptr;
  };
  const std::vector<ListedParam> differ = ListedParams(i, false);
  for (const ListedParam& p : differ) EXPECT_TRUE(p.differs) << p.name;
  const ListedParam* r = find(differ, "loop_search_maximum_distance");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->value, "6.5");
  ASSERT_NE(find(differ, "do_loop_closing"), nullptr);
  EXPECT_EQ(find(differ, "do_loop_closing")->value, "false");

  const std::vector<ListedParam> all = ListedParams(i, true);
  EXPECT_EQ(all.size(), slam::ToNamedValues(i.params).size());
  EXPECT_GT(all.size(), differ.size());
  const ListedParam* same = nullptr;
  for (const ListedParam& p : all) {
    if (!p.differs) same = &p;
  }
  ASSERT_NE(same, nullptr);
  EXPECT_EQ(find(differ, same->name), nullptr);
}

TEST_F(ParamsInspectionTest, WrittenValuesAreTheFilesOwnTextKeyByKey) {
  const std::string change = Write("written.yaml",
                                   "slam_toolbox:\n  ros__parameters:\n    loop_search_maximum_distance: 6.50\n"
                                   "    do_loop_closing: True\n");
  const ParamsInspection i = InspectParamsFiles({kToolbox, change}, "", {});
  const std::vector<std::string> written = WrittenValues(i.files[1]);
  ASSERT_EQ(written.size(), i.files[1].report.keys.size());
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(i.files[1].report.keys[0].key, "loop_search_maximum_distance");
  EXPECT_EQ(written[0], "6.50");
  EXPECT_EQ(written[1], "True");
  EXPECT_EQ(WrittenValues(i.files[0]).size(), i.files[0].report.keys.size());
}

}  // namespace
}  // namespace slamtune::tune
