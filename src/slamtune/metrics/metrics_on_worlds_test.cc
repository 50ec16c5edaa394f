#include <gtest/gtest.h>

#include <algorithm>

#include "slamtune/metrics/map_quality.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/pose_map.h"

namespace slamtune::metrics {
namespace {

// Do the metrics say what they should? On a built-in world the map drawn from the true
// poses must score lower on all three than the map drawn from drifting odometry.
void ExpectTruthBeatsOdometry(const std::string& world, std::size_t scans) {
  sim::SimulationOptions options;
  options.world = world;
  const sim::Simulation s = sim::Simulate(options);
  io::LaserLog log = s.log;
  log.scans.resize(std::min(scans, log.scans.size()));
  const slam::MapperParams params;
  const auto truth = ComputeMapQuality(slam::MapFromPoses(log, s.truth, params));
  const auto odom = ComputeMapQuality(slam::MapFromPoses(log, slam::OdometryTrajectory(log), params));
  EXPECT_LT(truth.occupied_ratio, odom.occupied_ratio) << world;
  EXPECT_LT(truth.corner_pixels, odom.corner_pixels) << world;
  EXPECT_LT(truth.enclosed_areas, odom.enclosed_areas) << world;
}

TEST(MetricsOnWorlds, TruthBeatsOdometryInTheOffice) { ExpectTruthBeatsOdometry("office", 100000); }
TEST(MetricsOnWorlds, TruthBeatsOdometryInTheCorridor) { ExpectTruthBeatsOdometry("corridor", 100000); }

}  // namespace
}  // namespace slamtune::metrics
