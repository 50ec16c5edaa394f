#include "slamtune/slam/pose_map.h"

#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::slam {
namespace {

TEST(PoseMap, DrawsEveryScanWithAPose) {
  sim::SimulationOptions options;
  const sim::Simulation s = sim::Simulate(options);
  io::LaserLog log = s.log;
  log.scans.resize(200);
  PoseMapSummary summary;
  const io::MapImage map = MapFromPoses(log, s.truth, MapperParams{}, &summary);
  EXPECT_EQ(summary.scans_drawn, 200);
  EXPECT_EQ(summary.scans_without_pose, 0);
  EXPECT_GT(map.width, 0);
  std::vector<io::TimedPose> half(s.truth.begin(), s.truth.begin() + 100);
  MapFromPoses(log, half, MapperParams{}, &summary);
  EXPECT_EQ(summary.scans_drawn, 100);
  EXPECT_EQ(summary.scans_without_pose, 100);
}

TEST(PoseMap, MismatchedTimestampsAreAnError) {
  sim::SimulationOptions options;
  const sim::Simulation s = sim::Simulate(options);
  io::LaserLog log = s.log;
  log.scans.resize(10);
  EXPECT_THROW(MapFromPoses(log, {{-1.0, Pose2{}}}, MapperParams{}), InputError);
}

}  // namespace
}  // namespace slamtune::slam
