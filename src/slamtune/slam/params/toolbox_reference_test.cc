// slam_toolbox's own mapping core (its lib/karto_sdk, Ceres back-end and SMapper::configure, ros2
// branch, package 2.7.0), built without ROS and fed the shared CARMEN logs as its asynchronous node
// feeds Karto, with the shipped mapper_params_online_async.yaml, makes these graphs; the engine
// at --preset slam_toolbox makes the same ones (every match and coarse loop check bit for bit:
// docs/ros-nodes.md). mit-killian (3643 nodes, 3835 edges, 155 loop closures) takes minutes and
// is checked by bench/ instead.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/slam/log_runner.h"

namespace slamtune::slam {
namespace {

struct NodeFigures {
  const char* log;
  int nodes;
  int edges;
  std::size_t loop_closures;
};

class SlamToolboxAtDefaults : public ::testing::TestWithParam<NodeFigures> {};

TEST_P(SlamToolboxAtDefaults, MakesTheNodesGraph) {
  const NodeFigures& f = GetParam();
  const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/" + f.log + ".clf.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  const RunResult run =
      RunLog(std::make_shared<const io::LaserLog>(io::ReadCarmenLog(path)), MapperParams::Preset("slam_toolbox"));
  EXPECT_EQ(run.summary.nodes, f.nodes);
  EXPECT_EQ(run.summary.total_edges(), f.edges);
  EXPECT_EQ(run.summary.loop_closures.size(), f.loop_closures);
}

INSTANTIATE_TEST_SUITE_P(SharedLogs, SlamToolboxAtDefaults,
                         ::testing::Values(NodeFigures{"aces", 694, 767, 27}, NodeFigures{"mit-csail", 675, 747, 30},
                                           NodeFigures{"intel", 1329, 1581, 134}),
                         [](const ::testing::TestParamInfo<NodeFigures>& info) {
                           std::string name = info.param.log;
                           name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                           return name;
                         });

}  // namespace
}  // namespace slamtune::slam
