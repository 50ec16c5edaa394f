#include "slamtune/slam/params/ros_node_files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/fixtures.h"
#include "slamtune/slam/params/params_yaml.h"

namespace slamtune::slam {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

std::string ReadFixture(const std::string& name) {
  std::ifstream in(slamtune::testing::FixturePath("params/" + name));
  EXPECT_TRUE(in) << name;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The engine parameters a node's file means: the node's defaults with the file applied.
MapperParams Meaning(RosNode node, const std::string& yaml) {
  MapperParams p = NodeDefaults(node);
  ApplyParamsYaml(p, yaml, "file");
  return p;
}

MapperParams Tuned(MapperParams p) {
  p.loop_search_maximum_distance = 5.25;
  p.loop_match_minimum_chain_size = 14;
  p.loop_match_minimum_response_coarse = 0.61;
  return p;
}

NodeFileInputs Inputs(const MapperParams& base, const std::string& base_text = "") {
  NodeFileInputs in;
  in.base = base;
  in.tuned = Tuned(base);
  in.base_file_text = base_text;
  in.comments = {"slamtune: better than the base"};
  return in;
}

TEST(CheckNodeFile, AcceptsAFileTheNodeLoads) {
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, ReadFixture("slam_toolbox_online_async.yaml")), IsEmpty());
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamKarto, ReadFixture("slam_karto_mapper_params.yaml")), IsEmpty());
}

TEST(CheckNodeFile, FindsWhatWouldStopOrMisleadTheNode) {
  const std::string ok = "slam_toolbox:\n  ros__parameters:\n";
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, ok + "    scan_buffer_size: 19.0\n"),
              ElementsAre(HasSubstr("scan_buffer_size: '19.0' reads as double, the node declares int")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, ok + "    loop_search_maximum_distance: 3\n"),
              ElementsAre(HasSubstr("reads as int, the node declares double")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, ok + "    do_loop_closing: \"true\"\n"),
              ElementsAre(HasSubstr("reads as string, the node declares bool")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, ok + "    loop_serch_maximum_distance: 3.0\n"),
              ElementsAre(HasSubstr("loop_serch_maximum_distance: not a slam_toolbox parameter")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, ok + "    solver_plugin: solver_plugins::SpaSolver\n"),
              ElementsAre(HasSubstr("is not registered by slam_toolbox")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, "loop_search_maximum_distance: 3.0\n"),
              ElementsAre(HasSubstr("nests its parameters as slam_toolbox: ros__parameters:")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamKarto, ok + "    loop_search_maximum_distance: 3.0\n"),
              ElementsAre(HasSubstr("a slam_karto file is a flat map")));
  // ROS 1 reads an int as a double, but not a double as an int.
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamKarto, "loop_search_maximum_distance: 4\n"), IsEmpty());
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamKarto, "scan_buffer_size: 70.0\n"),
              ElementsAre(HasSubstr("the node declares int")));
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, "slam_toolbox: [1, 2\n"), ElementsAre(HasSubstr("not valid YAML")));
}

TEST(CheckNodeFile, AcceptsTheWaysRos2NamesTheNode) {
  const std::string params = "  ros__parameters:\n    loop_search_maximum_distance: 3.0\n";
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, "/slam_toolbox:\n" + params), IsEmpty());
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, "/**:\n" + params), IsEmpty());
  // Another node's section beside it is that node's business.
  EXPECT_THAT(
      CheckNodeFile(RosNode::kSlamToolbox, "amcl:\n  ros__parameters:\n    alpha1: 0.2\nslam_toolbox:\n" + params),
      IsEmpty());
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox,
                            "amcl:\n  ros__parameters:\n    a: 1\nmap_server:\n"
                            "  ros__parameters:\n    b: 2\n"),
              ElementsAre(HasSubstr("none for slam_toolbox")));
}

TEST(MakeNodeFiles, FromScratchTheFilesLoadAndMeanTheTunedValues) {
  for (RosNode node : {RosNode::kSlamToolbox, RosNode::kSlamKarto}) {
    SCOPED_TRACE(RosNodeName(node));
    const NodeFileInputs in = Inputs(NodeDefaults(node));
    const NodeFiles files = MakeNodeFiles(node, in, true);
    EXPECT_THAT(CheckNodeFile(node, files.full), IsEmpty()) << files.full;
    EXPECT_THAT(CheckNodeFile(node, files.change), IsEmpty()) << files.change;
    EXPECT_EQ(Meaning(node, files.full), in.tuned) << files.full;
    EXPECT_EQ(Meaning(node, files.change), in.tuned) << files.change;
    const std::string r0 = node == RosNode::kSlamToolbox ? "3.0" : "4.0";
    EXPECT_THAT(files.changed, ElementsAre("loop_search_maximum_distance: " + r0 + " -> 5.25",
                                           "loop_match_minimum_chain_size: 10 -> 14",
                                           HasSubstr("loop_match_minimum_response_coarse: ")));
    EXPECT_THAT(files.full, ::testing::StartsWith("# slamtune: better than the base\n"));
    EXPECT_THAT(files.not_written, IsEmpty());
  }
}

TEST(MakeNodeFiles, TheToolboxFileHasNoTrapsAndTheDeclaredTypes) {
  const NodeFiles files = MakeNodeFiles(RosNode::kSlamToolbox, Inputs(NodeDefaults(RosNode::kSlamToolbox)), true);
  EXPECT_THAT(files.full, HasSubstr("slam_toolbox:\n  ros__parameters:\n"));
  EXPECT_THAT(files.full, HasSubstr("solver_plugin: solver_plugins::CeresSolver\n"));
  EXPECT_THAT(files.full, HasSubstr("scan_buffer_size: 10\n"));
  EXPECT_THAT(files.full, HasSubstr("loop_search_space_dimension: 8.0\n"));
  EXPECT_THAT(files.full, ::testing::Not(HasSubstr("minimum_time_interval")));
}

TEST(MakeNodeFiles, TheUsersFileKeepsItsLinesAndGetsTheTunedValues) {
  for (const auto& [node, fixture] : {std::pair{RosNode::kSlamToolbox, "slam_toolbox_online_async.yaml"},
                                      std::pair{RosNode::kSlamKarto, "slam_karto_mapper_params.yaml"}}) {
    SCOPED_TRACE(fixture);
    const std::string text = ReadFixture(fixture);
    const MapperParams base = Meaning(node, text);
    const NodeFileInputs in = Inputs(base, text);
    const NodeFiles files = MakeNodeFiles(node, in, true);
    EXPECT_THAT(CheckNodeFile(node, files.full), IsEmpty()) << files.full;
    EXPECT_THAT(CheckNodeFile(node, files.change), IsEmpty()) << files.change;
    EXPECT_EQ(Meaning(node, files.full), in.tuned);
    // base + change = full
    MapperParams merged = base;
    ApplyParamsYaml(merged, files.change, "change");
    EXPECT_EQ(merged, Meaning(node, files.full));
    // The user's comments and node-level keys are kept as written.
    EXPECT_THAT(files.full, HasSubstr("loop_search_maximum_distance: 5.25\n"));
    EXPECT_THAT(files.full, HasSubstr("loop_match_minimum_chain_size: 14\n"));
    if (node == RosNode::kSlamToolbox) {
      EXPECT_THAT(files.full, HasSubstr("    mode: mapping #localization\n"));
      EXPECT_THAT(files.full, HasSubstr("    minimum_time_interval: 0.5\n"));
      EXPECT_THAT(files.full, HasSubstr("    transform_publish_period: 0.02 # if 0 never publishes odometry\n"));
    } else {
      EXPECT_THAT(files.full, HasSubstr("loop_match_maximum_variance_coarse: 0.4     # squared by Karto's setter\n"));
      EXPECT_THAT(files.full, HasSubstr("minimum_time_interval: 3600\n"));
    }
  }
}

TEST(MakeNodeFiles, ABareRos2MapIsWrappedForTheNodeAndOtherNodesAreKept) {
  const std::string bare = "ros__parameters:\n  loop_search_maximum_distance: 3.0  # r\n  mode: mapping\n";
  NodeFiles files = MakeNodeFiles(RosNode::kSlamToolbox, Inputs(Meaning(RosNode::kSlamToolbox, bare), bare), true);
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, files.full), IsEmpty()) << files.full;
  EXPECT_THAT(files.full,
              HasSubstr("slam_toolbox:\n  ros__parameters:\n    loop_search_maximum_distance: 5.25  # r\n"));

  const std::string two =
      "amcl:\n  ros__parameters:\n    alpha1: 0.2\n/**:\n  ros__parameters:\n"
      "    loop_search_maximum_distance: 3.0\n";
  files = MakeNodeFiles(RosNode::kSlamToolbox, Inputs(Meaning(RosNode::kSlamToolbox, two), two), true);
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, files.full), IsEmpty()) << files.full;
  EXPECT_THAT(files.full, HasSubstr("amcl:\n  ros__parameters:\n    alpha1: 0.2\n/**:\n"));
  EXPECT_EQ(Meaning(RosNode::kSlamToolbox, files.full), Tuned(Meaning(RosNode::kSlamToolbox, two)));
}

TEST(MakeNodeFiles, AFlowMapIsWrittenAgainWhole) {
  const std::string flow =
      "slam_toolbox: {ros__parameters: {loop_search_maximum_distance: 3.0, scan_buffer_size: 10}}\n";
  const NodeFiles files =
      MakeNodeFiles(RosNode::kSlamToolbox, Inputs(Meaning(RosNode::kSlamToolbox, flow), flow), true);
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, files.full), IsEmpty()) << files.full;
  EXPECT_EQ(Meaning(RosNode::kSlamToolbox, files.full), Tuned(Meaning(RosNode::kSlamToolbox, flow)));
}

TEST(MakeNodeFiles, WithoutAChangeTheChangeFileHoldsOnlyItsComments) {
  NodeFileInputs in = Inputs(NodeDefaults(RosNode::kSlamToolbox));
  in.tuned = in.base;
  in.comments = {"slamtune: NOT better than the base"};
  const NodeFiles files = MakeNodeFiles(RosNode::kSlamToolbox, in, false);
  EXPECT_EQ(files.change, "# slamtune: NOT better than the base\n");
  EXPECT_THAT(files.changed, IsEmpty());
  EXPECT_THAT(CheckNodeFile(RosNode::kSlamToolbox, files.change), IsEmpty());
  EXPECT_EQ(Meaning(RosNode::kSlamToolbox, files.full), in.base);
}

TEST(MakeNodeFiles, ListsTunedValuesTheNodeCannotTake) {
  NodeFileInputs in = Inputs(NodeDefaults(RosNode::kSlamKarto));
  in.tuned.max_laser_range = 12.5;  // slam_karto has no parameter for it
  const NodeFiles files = MakeNodeFiles(RosNode::kSlamKarto, in, true);
  EXPECT_THAT(files.not_written, ElementsAre("max_laser_range"));
}

TEST(NodeOfParamsFile, TellsTheNodeFromTheLayout) {
  EXPECT_EQ(NodeOfParamsFile(ReadFixture("slam_toolbox_online_async.yaml"), "f"), RosNode::kSlamToolbox);
  EXPECT_EQ(NodeOfParamsFile(ReadFixture("slam_karto_mapper_params.yaml"), "f"), RosNode::kSlamKarto);
  EXPECT_EQ(NodeOfParamsFile("ros__parameters: {}\n", "f"), RosNode::kSlamToolbox);
  EXPECT_THROW(NodeOfParamsFile("a: [1\n", "f"), InputError);
}

TEST(NodeParams, EveryEngineNameIsAnEngineParameter) {
  for (RosNode node : {RosNode::kSlamToolbox, RosNode::kSlamKarto}) {
    for (const NodeParam& param : NodeParams(node)) {
      if (param.engine[0] == '\0') continue;
      EXPECT_NE(FindParam(param.engine), nullptr) << param.name;
    }
  }
}

}  // namespace
}  // namespace slamtune::slam
