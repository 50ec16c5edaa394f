#include "slamtune/slam/laser_scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slamtune::slam {
namespace {

std::shared_ptr<const LaserGeometry> ThreeBeamLaser() {
  auto g = std::make_shared<LaserGeometry>();
  g->min_angle = -kPi / 2;
  g->angular_resolution = kPi / 2;
  g->num_readings = 3;
  g->min_range = 0.1;
  g->max_range = 80;
  g->range_threshold = 12;
  return g;
}

TEST(LaserScan, PointReadoutFollowsSpec22) {
  const double inf = std::numeric_limits<double>::infinity();
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, 20.0, inf});
  LaserScan scan(ThreeBeamLaser(), ranges, Pose2{1, 2, kPi / 2}, 0.0);
  ASSERT_EQ(scan.unfiltered_points().size(), 3u);
  // Beam 0 at world angle 0: (2, 2). Beam 1 at pi/2, 20 m: beyond the threshold, unfiltered only.
  EXPECT_NEAR(scan.unfiltered_points()[0].x(), 2.0, 1e-12);
  EXPECT_NEAR(scan.unfiltered_points()[0].y(), 2.0, 1e-12);
  EXPECT_NEAR(scan.unfiltered_points()[1].y(), 22.0, 1e-12);
  EXPECT_FALSE(std::isfinite(scan.unfiltered_points()[2].x()));
  ASSERT_EQ(scan.filtered_points().size(), 1u);
  EXPECT_NEAR(scan.barycenter().x, 2.0, 1e-12);
  EXPECT_NEAR(scan.barycenter().y, 2.0, 1e-12);
  EXPECT_NEAR(scan.bounding_box().min.x(), 1.0, 1e-12);
  EXPECT_NEAR(scan.bounding_box().max.x(), 2.0, 1e-12);
}

TEST(LaserScan, BarycenterFallsBackToSensorPose) {
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{50.0, 50.0, 50.0});
  LaserScan scan(ThreeBeamLaser(), ranges, Pose2{1, 2, 0.3}, 0.0);
  EXPECT_EQ(scan.barycenter(), (Pose2{1, 2, 0.3}));
}

TEST(LaserScan, SensorPoseRoundTripsThroughOffset) {
  auto g = std::make_shared<LaserGeometry>(*ThreeBeamLaser());
  g->offset = {0.2, -0.1, 0.3};
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, 1.0, 1.0});
  LaserScan scan(g, ranges, Pose2{0, 0, 0}, 0.0);
  const Pose2 sensor{3, 4, 1.0};
  scan.SetSensorPose(sensor);
  EXPECT_NEAR(scan.SensorPose().x, 3.0, 1e-12);
  EXPECT_NEAR(scan.SensorPose().y, 4.0, 1e-12);
  EXPECT_NEAR(scan.SensorPose().theta, 1.0, 1e-12);
}

}  // namespace
}  // namespace slamtune::slam
