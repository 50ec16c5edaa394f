#include "slamtune/sim/laser_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

using V = Eigen::Vector2d;

RayCaster Box(double w, double h) {
  return RayCaster({{V(0, 0), V(w, 0)}, {V(w, 0), V(w, h)}, {V(w, h), V(0, h)}, {V(0, h), V(0, 0)}});
}

TEST(LaserOptions, DefaultsAreASickLms) {
  const LaserOptions laser;
  EXPECT_NO_THROW(laser.Validate());
  EXPECT_EQ(laser.beams, 181);
  EXPECT_DOUBLE_EQ(laser.fov_deg, 180.0);
  EXPECT_DOUBLE_EQ(laser.max_range_m, 30.0);
  EXPECT_DOUBLE_EQ(laser.range_noise_m, 0.01);
  EXPECT_DOUBLE_EQ(laser.angle_min(), -kPi / 2);
  EXPECT_DOUBLE_EQ(laser.angle_increment(), kPi / 180);
}

TEST(LaserOptions, ValidateNamesFieldValueAndRule) {
  LaserOptions laser;
  laser.beams = 1;
  EXPECT_THAT([&] { laser.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("laser beams = 1: must be in [2, 100000]")));
  laser = LaserOptions();
  laser.fov_deg = 400;
  EXPECT_THAT([&] { laser.Validate(); }, ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("fov_deg = 400")));
  laser = LaserOptions();
  laser.max_range_m = -1;
  EXPECT_THAT([&] { laser.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("max_range_m = -1")));
  laser = LaserOptions();
  laser.range_noise_m = -0.1;
  EXPECT_THAT([&] { laser.Validate(); }, ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("range_noise_m")));
  laser = LaserOptions();
  laser.range_resolution_m = 0.003;  // 1/0.003 is not whole
  EXPECT_THAT([&] { laser.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("range_resolution_m")));
}

TEST(SimulateScan, NoiselessReadingsAreExactDistances) {
  LaserOptions laser;
  laser.range_noise_m = 0.0;
  Random random(1);
  // Laser at (4, 3) facing +y in a 10 x 8 box: beam 0 looks at -x (right side is -90 deg).
  const SimulatedScan scan = SimulateScan(Box(10, 8), Pose2{4, 3, kPi / 2}, laser, random);
  ASSERT_EQ(scan.ranges.size(), 181u);
  EXPECT_DOUBLE_EQ(scan.ranges[0], 6.0);     // -90 deg: towards +x wall at x = 10
  EXPECT_DOUBLE_EQ(scan.ranges[90], 5.0);    // straight ahead: y = 8
  EXPECT_DOUBLE_EQ(scan.ranges[180], 4.0);   // +90 deg: x = 0
  EXPECT_DOUBLE_EQ(scan.ranges[45], 7.071);  // world 45 deg: y = 8 after 5 * sqrt(2) = 7.0711 m
  EXPECT_EQ(scan.no_returns, 0u);
}

TEST(SimulateScan, NoReturnReadsExactlyMaxRange) {
  LaserOptions laser;
  laser.max_range_m = 5.0;
  Random random(2);
  // One wall 3 m ahead; everything else open or beyond 5 m.
  const RayCaster caster({{V(3, -1), V(3, 1)}, {V(-6, -10), V(-6, 10)}});
  const SimulatedScan scan = SimulateScan(caster, Pose2{0, 0, 0}, laser, random);
  EXPECT_NEAR(scan.ranges[90], 3.0, 0.05);
  EXPECT_EQ(scan.ranges[0], 5.0);    // open to the right
  EXPECT_EQ(scan.ranges[180], 5.0);  // open to the left
  std::size_t at_max = 0;
  for (double r : scan.ranges) {
    EXPECT_LE(r, 5.0);
    at_max += r == 5.0;
  }
  EXPECT_EQ(scan.no_returns, at_max);
  EXPECT_GT(at_max, 100u);
}

TEST(SimulateScan, NoiseHasTheRequestedSigmaAndMillimetreSteps) {
  LaserOptions laser;
  laser.beams = 2;
  laser.fov_deg = 1e-6;  // both beams straight ahead
  laser.range_noise_m = 0.02;
  Random random(5);
  const RayCaster caster({{V(7, -1), V(7, 1)}});
  double sum = 0.0, sum2 = 0.0;
  const int n = 5000;
  for (int i = 0; i < n; ++i) {
    const SimulatedScan scan = SimulateScan(caster, Pose2{0, 0, 0}, laser, random);
    for (double r : scan.ranges) {
      EXPECT_NEAR(r * 1000.0, std::round(r * 1000.0), 1e-6);
      sum += r - 7.0;
      sum2 += (r - 7.0) * (r - 7.0);
    }
  }
  const double mean = sum / (2 * n);
  EXPECT_NEAR(mean, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sum2 / (2 * n) - mean * mean), 0.02, 0.001);
}

}  // namespace
}  // namespace slamtune::sim
