#include "slamtune/slam/front_end.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace slamtune::slam {
namespace {

using ::testing::ElementsAre;

LaserScan ScanAt(const Pose2& odometric, double time, const Pose2& offset = {}) {
  auto g = std::make_shared<LaserGeometry>();
  g->min_angle = 0;
  g->angular_resolution = 0.1;
  g->num_readings = 1;
  g->offset = offset;
  return LaserScan(g, std::make_shared<const std::vector<double>>(std::vector<double>{1.0}), odometric, time);
}

TEST(InitialGuess, AppliesOdometryIncrementToLastCorrectedPose) {
  const Pose2 last_odom{1, 1, 0.2}, last_corrected{3, -1, 1.0}, odom{2, 1.5, 0.5};
  const Pose2 guess = InitialGuess(last_odom, last_corrected, odom);
  const Pose2 expected = Compose(last_corrected, Between(last_odom, odom));  // B (+) (A (-) P)
  EXPECT_NEAR(guess.x, expected.x, 1e-12);
  EXPECT_NEAR(guess.y, expected.y, 1e-12);
  EXPECT_NEAR(guess.theta, expected.theta, 1e-12);
  EXPECT_EQ(InitialGuess(last_odom, last_odom, odom), odom);
}

TEST(HasMovedEnough, ThreeOredTestsOnOdometricSensorPoses) {
  const MovementOptions o{10.0, 0.2, 0.174};
  const LaserScan last = ScanAt({0, 0, 0}, 0.0);
  EXPECT_EQ(HasMovedEnough(last, nullptr, o), MoveDecision::kFirstScan);
  EXPECT_EQ(HasMovedEnough(ScanAt({0.1, 0, 0}, 9.0), &last, o), MoveDecision::kNotMoved);
  EXPECT_EQ(HasMovedEnough(ScanAt({0.1, 0, 0}, 10.0), &last, o), MoveDecision::kTime);
  EXPECT_EQ(HasMovedEnough(ScanAt({0, 0, 0.174}, 0.0), &last, o), MoveDecision::kHeading);
  EXPECT_EQ(HasMovedEnough(ScanAt({0, 0, -0.174}, 0.0), &last, o), MoveDecision::kHeading);
  EXPECT_EQ(HasMovedEnough(ScanAt({0, 0, 0.173}, 0.0), &last, o), MoveDecision::kNotMoved);
  // Distance: d^2 >= 0.04 - 1e-6.
  EXPECT_EQ(HasMovedEnough(ScanAt({0.2, 0, 0}, 0.0), &last, o), MoveDecision::kDistance);
  EXPECT_EQ(HasMovedEnough(ScanAt({std::sqrt(0.04 - 0.9e-6), 0, 0}, 0.0), &last, o), MoveDecision::kDistance);
  EXPECT_EQ(HasMovedEnough(ScanAt({std::sqrt(0.04 - 1.1e-6), 0, 0}, 0.0), &last, o), MoveDecision::kNotMoved);
  // Heading wraps: 3.1 -> -3.1 is a turn of 0.083 rad.
  const LaserScan last_turned = ScanAt({0, 0, 3.1}, 0.0);
  EXPECT_EQ(HasMovedEnough(ScanAt({0, 0, -3.1}, 0.0), &last_turned, o), MoveDecision::kNotMoved);
}

TEST(HasMovedEnough, IgnoresCorrectedPoses) {
  const MovementOptions o{3600, 0.2, 0.174};
  LaserScan last = ScanAt({0, 0, 0}, 0.0);
  last.SetCorrectedPose({5, 5, 1.0});  // a correction does not count as motion
  LaserScan scan = ScanAt({0.05, 0, 0}, 0.0);
  EXPECT_EQ(HasMovedEnough(scan, &last, o), MoveDecision::kNotMoved);
}

TEST(HasMovedEnough, UsesSensorPosesWithAnOffset) {
  // Turning in place by 0.1 rad moves a laser mounted 3 m ahead by 0.3 m.
  const MovementOptions o{3600, 0.2, 0.174};
  const Pose2 offset{3, 0, 0};
  const LaserScan last = ScanAt({0, 0, 0}, 0.0, offset);
  EXPECT_EQ(HasMovedEnough(ScanAt({0, 0, 0.1}, 0.0, offset), &last, o), MoveDecision::kDistance);
}

TEST(TrimRunningBuffer, ByCountAndByFrontBackDistance) {
  std::map<int, Pose2> poses;
  for (int i = 0; i < 10; ++i) poses[i] = {0.5 * i, 0, 0};
  auto pose = [&](int id) { return poses.at(id); };
  std::deque<int> buffer{0, 1, 2, 3, 4};
  TrimRunningBuffer(buffer, pose, 3, 100.0);
  EXPECT_THAT(buffer, ElementsAre(2, 3, 4));
  buffer = {0, 1, 2, 3, 4};  // d^2 > 1.5^2 - 1e-6 drops the front: 2.0 m and exactly 1.5 m spans go
  TrimRunningBuffer(buffer, pose, 70, 1.5);
  EXPECT_THAT(buffer, ElementsAre(2, 3, 4));
  buffer = {0, 1, 2, 3, 4};
  TrimRunningBuffer(buffer, pose, 70, std::sqrt(4.0 + 0.5e-6));  // d^2 = 4 > 4 + 0.5e-6 - 1e-6: drop
  EXPECT_THAT(buffer, ElementsAre(1, 2, 3, 4));
  buffer = {0, 1, 2, 3, 4};
  TrimRunningBuffer(buffer, pose, 70, std::sqrt(4.0 + 1.5e-6));  // kept
  EXPECT_THAT(buffer, ElementsAre(0, 1, 2, 3, 4));
}

// Karto's ComputeWeightedMean divides the sums of cosines and sines by the number of means
// before atan2; on these three headings that gives a result one ulp below atan2 of the sums.
TEST(WeightedMean, HeadingIsAtan2OfTheMeanCosineAndSine) {
  const std::vector<Pose2> means{
      {0, 0, 0.14000000000000001}, {0, 0, -0.050000000000000003}, {0, 0, 1.3899999999999999}};
  const std::vector<Eigen::Matrix3d> covs(3, Eigen::Matrix3d::Identity());
  double sum_cos = 0.0, sum_sin = 0.0;
  for (const Pose2& m : means) {
    sum_cos += std::cos(m.theta);
    sum_sin += std::sin(m.theta);
  }
  const double heading = WeightedMean(means, covs).theta;
  EXPECT_EQ(heading, std::atan2(sum_sin / 3.0, sum_cos / 3.0));
  EXPECT_EQ(heading, 0x1.d6907d2c3dda1p-2);
  EXPECT_EQ(std::atan2(sum_sin, sum_cos), 0x1.d6907d2c3dda2p-2);  // the undivided sums
}

TEST(WeightedMean, InverseCovarianceWeightsAndCircularHeading) {
  const std::vector<Pose2> means{{0, 0, 0.1}, {1, 2, 0.3}};
  const std::vector<Eigen::Matrix3d> covs{Eigen::Vector3d(1.0, 4.0, 1.0).asDiagonal(),
                                          Eigen::Vector3d(3.0, 4.0, 1.0).asDiagonal()};
  const Pose2 m = WeightedMean(means, covs);
  EXPECT_NEAR(m.x, 0.25, 1e-12);  // weights 3/4 and 1/4
  EXPECT_NEAR(m.y, 1.0, 1e-12);   // equal weights
  EXPECT_NEAR(m.theta, 0.2, 1e-12);
  const Pose2 single = WeightedMean(std::span(means).first(1), std::span(covs).first(1));
  EXPECT_NEAR(single.x, 0.0, 1e-15);
  EXPECT_NEAR(single.theta, 0.1, 1e-15);
  // Headings across +-pi average to pi, not 0.
  const std::vector<Pose2> wrap{{0, 0, 3.1}, {0, 0, -3.1}};
  const std::vector<Eigen::Matrix3d> unit{Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity()};
  EXPECT_NEAR(std::fabs(WeightedMean(wrap, unit).theta), kPi, 1e-12);
}

}  // namespace
}  // namespace slamtune::slam
