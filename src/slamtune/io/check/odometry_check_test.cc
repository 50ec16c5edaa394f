#include "slamtune/io/check/odometry_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/io/testing/straight_drive_log.h"

namespace slamtune::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// 20 s of driving along x at 0.5 m/s: ODOM at 10 Hz with its speed (`with_odometry`), scans at
// 5 Hz posed on the same line.
LaserLog DriveLog(bool with_odometry) {
  return testing::StraightDriveLog({.start_s = 10.0, .odometry_records = with_odometry ? 200 : 0, .scans = 100});
}

TEST(OdometryCheck, SaysWhichOdometryItChecked) {
  CheckReport report;
  CheckOdometry(DriveLog(true), {}, &report);
  EXPECT_THAT(report.facts, ElementsAre("odometry: 200 ODOM records, median period 0.1000 s, with velocities"));
  EXPECT_TRUE(report.problems.empty());

  CheckReport from_scans;
  CheckOdometry(DriveLog(false), {}, &from_scans);
  EXPECT_THAT(from_scans.facts, ElementsAre("odometry: 100 scan poses, median period 0.2000 s"));
  EXPECT_TRUE(from_scans.problems.empty());
}

TEST(OdometryCheck, AJumpIsListedAtTheScanAtOrBeforeIt) {
  LaserLog log = DriveLog(true);
  for (std::size_t k = 55; k < log.odometry.size(); ++k) log.odometry[k].pose.x += 2.0;  // at 15.5 s
  CheckReport report;
  CheckOdometry(log, {}, &report);
  ASSERT_EQ(report.problems.size(), 1u);
  const CheckProblem& jump = report.problems[0];
  EXPECT_EQ(jump.kind, ProblemKind::kOdometryJump);
  EXPECT_EQ(jump.count, 1u);
  EXPECT_EQ(jump.scans, (std::vector<std::size_t>{27}));  // the scan of 15.4 s
  EXPECT_DOUBLE_EQ(jump.times_s[0], 10.0 + 0.1 * 55);
  EXPECT_THAT(jump.what, HasSubstr("1 odometry jumps (faster than 3 m/s"));
}

TEST(OdometryCheck, ScanPosesAreNotCheckedForStallsOrVelocities) {
  LaserLog log = DriveLog(false);
  for (std::size_t k = 50; k < log.scans.size(); ++k) log.scans[k].ipc_time += 5.0;  // 5 s without scans
  CheckReport report;
  CheckOdometry(log, {}, &report);
  EXPECT_TRUE(report.problems.empty()) << report.problems[0].what;
}

TEST(OdometryCheck, FewerThanTwoPosesSayNothing) {
  LaserLog log = DriveLog(false);
  log.scans.resize(1);
  CheckReport report;
  CheckOdometry(log, {}, &report);
  EXPECT_TRUE(report.facts.empty());
  EXPECT_TRUE(report.problems.empty());
}

}  // namespace
}  // namespace slamtune::io
