#include "slamtune/slam/matching/match_covariance.h"

#include <gtest/gtest.h>

#include <vector>

namespace slamtune::slam {
namespace {

// Loop-matcher coarse lattice: 81 x 81 positions 2 rho = 0.1 m apart around the centre.
constexpr double kRho = 0.05;
constexpr double kOffset = 0.5 * 160 * kRho;  // 4 m
constexpr double kStep = 2 * kRho;
constexpr double kAngleStep = 0.0349066;

SearchProbabilityGrid GridAround(const Pose2& center) {
  SearchProbabilityGrid grid(161, kRho);
  grid.Reset({center.x - kOffset, center.y - kOffset});
  return grid;
}

TEST(PositionalCovariance, NoOverlapGivesMaxVariance) {
  const Pose2 center{1, 2, 0};
  const SearchProbabilityGrid grid = GridAround(center);
  const Eigen::Matrix3d cov = PositionalCovariance(center, 0.0, center, kOffset, kStep, kAngleStep, grid);
  EXPECT_EQ(cov(0, 0), 500.0);
  EXPECT_EQ(cov(1, 1), 500.0);
  EXPECT_EQ(cov(2, 2), 4 * kAngleStep * kAngleStep);
  EXPECT_EQ(cov(0, 1), 0.0);
}

TEST(PositionalCovariance, SinglePeakIsFlooredAtATenthOfAStepSquared) {
  const Pose2 center{1, 2, 0.3};
  SearchProbabilityGrid grid = GridAround(center);
  grid.at(grid.IndexOf(center.x, center.y)) = 0.8;
  const Eigen::Matrix3d cov = PositionalCovariance(center, 0.8, center, kOffset, kStep, kAngleStep, grid);
  const double floor = 0.1 * kStep * kStep;  // 0.001 m^2 for the loop matcher
  EXPECT_DOUBLE_EQ(cov(0, 0), floor * (1.0 / 0.8));
  EXPECT_DOUBLE_EQ(cov(1, 1), floor * (1.0 / 0.8));
  EXPECT_EQ(cov(0, 1), 0.0);
  // The heading entry is not scaled by 1/best.
  EXPECT_DOUBLE_EQ(cov(2, 2), 4 * kAngleStep * kAngleStep);
}

TEST(PositionalCovariance, WeightsPositionsWithinPointOneOfTheBest) {
  const Pose2 center{0, 0, 0};
  SearchProbabilityGrid grid = GridAround(center);
  grid.at(grid.IndexOf(0.0, 0.0)) = 0.8;
  grid.at(grid.IndexOf(kStep, 0.0)) = 0.75;      // inside the window (>= 0.7)
  grid.at(grid.IndexOf(0.0, kStep)) = 0.69;      // outside
  grid.at(grid.IndexOf(-kStep, -kStep)) = 0.71;  // inside
  const Eigen::Matrix3d cov = PositionalCovariance(center, 0.8, center, kOffset, kStep, kAngleStep, grid);
  const double norm = 0.8 + 0.75 + 0.71;
  const double vxx = (kStep * kStep * 0.75 + kStep * kStep * 0.71) / norm;
  const double vxy = (kStep * kStep * 0.71) / norm;
  const double vyy = (kStep * kStep * 0.71) / norm;
  EXPECT_NEAR(cov(0, 0), vxx / 0.8, 1e-15);
  EXPECT_NEAR(cov(0, 1), vxy / 0.8, 1e-15);
  EXPECT_NEAR(cov(1, 0), vxy / 0.8, 1e-15);
  EXPECT_NEAR(cov(1, 1), vyy / 0.8, 1e-15);
}

TEST(PositionalCovariance, SpreadIsMeasuredAroundTheBestMean) {
  const Pose2 center{0, 0, 0};
  SearchProbabilityGrid grid = GridAround(center);
  grid.at(grid.IndexOf(1.0, 0.0)) = 0.9;
  const Pose2 best{1.0, 0.0, 0.0};
  const Eigen::Matrix3d cov = PositionalCovariance(best, 0.9, center, kOffset, kStep, kAngleStep, grid);
  EXPECT_DOUBLE_EQ(cov(0, 0), 0.1 * kStep * kStep * (1.0 / 0.9));  // zero spread -> floor
}

TEST(PositionalCovarianceDeathTest, PositionOutsideTheProbabilityGridIsAnInvariantViolation) {
  const SearchProbabilityGrid grid = GridAround({0, 0, 0});
  EXPECT_DEATH(grid.IndexOf(4.1, 0.0), "probability");
}

TEST(AngularVariance, SpreadOfUnpenalisedResponsesAroundTheBestHeading) {
  const std::vector<double> angles = {0.1, 0.2, 0.3};
  const std::vector<double> raw = {0.5, 0.9, 0.85};
  // best 0.88 (penalised): window >= 0.78 keeps 0.2 and 0.3.
  const double v = AngularVariance(0.2, 0.88, 0.2, 0.1, angles, raw);
  const double expected = (0.0 * 0.9 + (0.1 * 0.1) * 0.85) / (0.9 + 0.85);
  EXPECT_NEAR(v, expected, 1e-15);
}

TEST(AngularVariance, SingleHeadingIsSeededWithOneStepSquared) {
  const std::vector<double> angles = {0.1, 0.2, 0.3};
  const std::vector<double> raw = {0.1, 0.9, 0.1};
  EXPECT_DOUBLE_EQ(AngularVariance(0.2, 0.9, 0.2, 0.1, angles, raw), (0.1 * 0.1) / 0.9);
}

TEST(AngularVariance, NoResponseFallsBackToThousandStepsSquared) {
  const std::vector<double> angles = {0.1, 0.2, 0.3};
  const std::vector<double> raw = {0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(AngularVariance(0.2, 0.0, 0.2, 0.1, angles, raw), 1000 * 0.1 * 0.1);
}

TEST(AngularVariance, BestHeadingIsUnwrappedTowardsTheCentre) {
  // Centre near +pi, best reported as -pi + 0.01: it is measured as pi + 0.01.
  const double c = kPi - 0.05;
  const std::vector<double> angles = {c, c + 0.06};
  const std::vector<double> raw = {0.0, 0.9};
  const double v = AngularVariance(-kPi + 0.01, 0.9, c, 0.06, angles, raw);
  EXPECT_NEAR(v, 0.06 * 0.06 / 0.9, 1e-12);  // zero spread around pi + 0.01 -> seed / norm
}

}  // namespace
}  // namespace slamtune::slam
