#include "slamtune/tune/pose_map_render.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/io/map_image.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class PoseMapRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::UniqueTempDir("pose_map_render");
    sim::SimulationOptions world;
    world.seed = 5;
    const sim::Simulation s = sim::Simulate(world);
    io::WriteCarmenLog((dir_ / "office.clf").string(), s.log);
    io::WriteTrajectory((dir_ / "truth.txt").string(), s.truth);
    options_.inputs.log = (dir_ / "office.clf").string();
    options_.inputs.input.max_scans = 200;
    options_.poses = (dir_ / "truth.txt").string();
    options_.out = (dir_ / "out").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  RenderOptions options_;
};

TEST_F(PoseMapRender, TheTrueTrajectoryDrawsEveryScanAndTheMapIsWritten) {
  const RenderOutcome outcome = RenderAndWrite(options_);
  EXPECT_EQ(outcome.summary.scans_drawn, 200);
  EXPECT_EQ(outcome.summary.scans_without_pose, 0);
  for (const char* name : {"map.pgm", "map.yaml", "map.png"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir_ / "out" / name)) << name;
  }
  const io::MapImage map = io::ReadMap((dir_ / "out" / "map.yaml").string());
  EXPECT_EQ(map.width, outcome.width);
  EXPECT_EQ(map.height, outcome.height);
  EXPECT_EQ(outcome.quality.width, outcome.width);
  EXPECT_GT(outcome.quality.occupied_cells, 0);
}

TEST_F(PoseMapRender, OdometryDrawsTheLogsOwnPoses) {
  options_.poses = kOdometryPoses;
  const RenderOutcome odometry = RenderAndWrite(options_);
  EXPECT_EQ(odometry.summary.scans_drawn, 200);
  options_.poses = (dir_ / "truth.txt").string();
  const RenderOutcome truth = RenderAndWrite(options_);
  EXPECT_NE(odometry.quality.occupied_cells, truth.quality.occupied_cells);
}

TEST_F(PoseMapRender, TheTrajectoryAndTheFolderAreCheckedBeforeTheLogIsRead) {
  options_.inputs.log = (dir_ / "missing.clf").string();
  options_.poses = (dir_ / "missing.txt").string();
  EXPECT_THAT([&] { RenderAndWrite(options_); }, ThrowsMessage<InputError>(HasSubstr("missing.txt")));
  options_.poses = kOdometryPoses;
  std::ofstream(dir_ / "file") << "x";
  options_.out = (dir_ / "file").string();
  EXPECT_THAT([&] { RenderAndWrite(options_); }, ThrowsMessage<InputError>(HasSubstr("is a file")));
}

TEST_F(PoseMapRender, ATrajectoryWithNoPoseAtAnyScanIsRefused) {
  io::WriteTrajectory((dir_ / "elsewhen.txt").string(), {{1.0, Pose2{}}, {2.0, Pose2{1.0, 0.0, 0.0}}});
  options_.poses = (dir_ / "elsewhen.txt").string();
  EXPECT_THROW(RenderAndWrite(options_), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "map.pgm"));
}

}  // namespace
}  // namespace slamtune::tune
