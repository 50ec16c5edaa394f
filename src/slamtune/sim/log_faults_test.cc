#include "slamtune/sim/log_faults.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

constexpr double kStep = 0.05;  // m between consecutive robot poses

// A synthetic CARMEN-like log: the robot drives `poses` steps of kStep m, alternately an ODOM
// record and a scan (file lines 1, 2, ... in that order), along a straight line in +x or, with
// `curvature` != 0, along a circle; every scan has its own readings and the laser `offset`.
io::LaserLog SyntheticLog(std::size_t poses, double curvature = 0.0, const Pose2& offset = {}) {
  io::LaserLog log;
  log.path = "synthetic.clf";
  Pose2 pose{1.0, 2.0, 0.0};
  for (std::size_t k = 0; k < poses; ++k) {
    const double time = 100.0 + 0.1 * static_cast<double>(k);
    if (k % 2 == 0) {
      io::OdomRecord odom;
      odom.line = k + 1;
      odom.pose = pose;
      odom.tv = 0.5;
      odom.ipc_time = odom.logger_time = time;
      log.odometry.push_back(odom);
    } else {
      io::LaserScanRecord scan;
      scan.line = k + 1;
      scan.ranges = {1.0 + 0.001 * static_cast<double>(k), 2.0, 3.0};
      scan.robot_pose = pose;
      scan.laser_pose = Compose(pose, offset);
      scan.laser_offset = Between(scan.robot_pose, scan.laser_pose);
      scan.ipc_time = scan.logger_time = time;
      log.scans.push_back(scan);
    }
    const double turn = curvature * kStep;
    pose = Compose(pose, Pose2{kStep, 0.0, turn});
  }
  return log;
}

// Robot poses of the log in file order (ODOM and scans alternate).
std::vector<Pose2> RobotPoses(const io::LaserLog& log) {
  std::vector<Pose2> poses;
  for (std::size_t i = 0; i < log.odometry.size() || i < log.scans.size(); ++i) {
    if (i < log.odometry.size()) poses.push_back(log.odometry[i].pose);
    if (i < log.scans.size()) poses.push_back(log.scans[i].robot_pose);
  }
  return poses;
}

void ExpectNear(const Pose2& a, const Pose2& b, double tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(NormalizeAngle(a.theta - b.theta), 0.0, tolerance) << what;
}

// A jump of 1 m over 0.5 m starting 2.01 m along: poses up to there are the original bits, poses
// after 2.51 m are 1 m further on, and in between the extra travel grows with the travel.
TEST(PlantLogFaults, JumpMovesEverythingAfterTheStretchOnByItsMagnitude) {
  const io::LaserLog plain = SyntheticLog(200);  // 9.95 m
  io::LaserLog log = plain;
  const LogFaultSummary summary = PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kJump, 2.01, 0.5, 1.0}});
  EXPECT_NEAR(summary.travel_m, 199 * kStep, 1e-9);
  EXPECT_EQ(summary.poses, 200u);
  EXPECT_EQ(summary.order, "file order");
  const std::vector<Pose2> before = RobotPoses(plain), after = RobotPoses(log);
  for (std::size_t k = 0; k < before.size(); ++k) {
    const double travel = kStep * static_cast<double>(k);
    if (travel < 2.01) {
      ASSERT_EQ(after[k], before[k]) << "pose " << k << " before the stretch changed";
    } else if (travel > 2.51) {
      ExpectNear(after[k], Pose2{before[k].x + 1.0, before[k].y, before[k].theta}, 1e-9, "after the stretch");
    } else {
      ExpectNear(after[k], Pose2{before[k].x + 2.0 * (travel - 2.01), before[k].y, 0.0}, 1e-9, "within");
    }
  }
  ASSERT_EQ(summary.faults.size(), 1u);
  const PlantedLogFault& planted = summary.faults[0];
  EXPECT_NEAR(planted.shift_m, 1.0, 1e-9);
  EXPECT_NEAR(planted.turn_rad, 0.0, 1e-12);
  ExpectNear(planted.displacement, Pose2{1.0, 0.0, 0.0}, 1e-9, "displacement");
  // Pose 41 (2.05 m) is the first scan past 2.01 m: scan 20; the scans at 2.05 .. 2.45 m lie within.
  ASSERT_TRUE(planted.first_scan.has_value());
  EXPECT_EQ(*planted.first_scan, 20u);
  EXPECT_EQ(planted.first_time, plain.scans[20].ipc_time - plain.scans[0].ipc_time);
  EXPECT_EQ(planted.scans_within, 5u);
  EXPECT_THAT(planted.Describe(), ::testing::HasSubstr("jump at 2.01 m over 0.5 m"));
  EXPECT_THAT(planted.Describe(), ::testing::HasSubstr("from scan 20"));
}

// Readings, timestamps, lines, velocities and everything but the odometric poses stay as they were.
TEST(PlantLogFaults, KeepsReadingsTimesAndEverythingButThePoses) {
  const io::LaserLog plain = SyntheticLog(120, 0.3, Pose2{0.2, -0.1, 0.05});
  io::LaserLog log = plain;
  PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kReverse, 1.0, 2.0}});
  ASSERT_EQ(log.scans.size(), plain.scans.size());
  ASSERT_EQ(log.odometry.size(), plain.odometry.size());
  for (std::size_t i = 0; i < plain.scans.size(); ++i) {
    const io::LaserScanRecord &a = plain.scans[i], &b = log.scans[i];
    EXPECT_EQ(a.ranges, b.ranges);
    EXPECT_EQ(a.ipc_time, b.ipc_time);
    EXPECT_EQ(a.logger_time, b.logger_time);
    EXPECT_EQ(a.line, b.line);
    EXPECT_EQ(a.laser_offset, b.laser_offset);
    // The laser follows its robot pose.
    ExpectNear(b.laser_pose, Compose(b.robot_pose, b.laser_offset), 1e-12, "laser = robot (+) offset");
  }
  for (std::size_t i = 0; i < plain.odometry.size(); ++i) {
    EXPECT_EQ(plain.odometry[i].ipc_time, log.odometry[i].ipc_time);
    EXPECT_EQ(plain.odometry[i].tv, log.odometry[i].tv);
  }
}

// A 60 deg spin over 0.1 m on a straight path: the rest of the path turns about the stretch.
TEST(PlantLogFaults, SpinTurnsThePathAfterTheStretchAboutIt) {
  const io::LaserLog plain = SyntheticLog(100);
  io::LaserLog log = plain;
  const double spin = DegToRad(60.0);
  const LogFaultSummary summary = PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kSpin, 1.0, 0.1, spin}});
  const std::vector<Pose2> before = RobotPoses(plain), after = RobotPoses(log);
  // The stretch covers the steps to poses 21 and 22 (1.0 .. 1.1 m): half the turn in each.
  const Pose2 pivot = after[22];
  ExpectNear(pivot, Pose2{1.0 + 1.05 + 0.05 * std::cos(spin / 2.0), 2.0 + 0.05 * std::sin(spin / 2.0), spin}, 1e-9,
             "end of the stretch");
  for (std::size_t k = 23; k < before.size(); ++k) {
    const double t = before[k].x - before[22].x;
    ExpectNear(after[k], Pose2{pivot.x + t * std::cos(spin), pivot.y + t * std::sin(spin), spin}, 1e-9, "after");
  }
  EXPECT_NEAR(summary.faults[0].turn_rad, spin, 1e-12);
}

// Reverse over 1 m: the travel over the stretch is reported backwards, so the path after it lies
// 2 m back along the heading, and within it the pose moves back as the robot moves on.
TEST(PlantLogFaults, ReverseReportsTheStretchBackwards) {
  const io::LaserLog plain = SyntheticLog(100);
  io::LaserLog log = plain;
  const LogFaultSummary summary = PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kReverse, 1.5, 1.0}});
  const std::vector<Pose2> before = RobotPoses(plain), after = RobotPoses(log);
  for (std::size_t k = 0; k < before.size(); ++k) {
    const double travel = kStep * static_cast<double>(k);
    const double expected = travel <= 1.5 ? travel : travel <= 2.5 ? 3.0 - travel : travel - 2.0;
    ExpectNear(after[k], Pose2{1.0 + expected, 2.0, 0.0}, 1e-9, "pose " + std::to_string(k));
  }
  EXPECT_NEAR(summary.faults[0].shift_m, 2.0, 1e-9);
}

// Increments are composed in the robot frame: on a curved path, every step after the stretch is
// the original step, and every pose after it is the summary's displacement (+) the original.
TEST(PlantLogFaults, OnACurveThePathAfterTheStretchIsTheOriginalMovedRigidly) {
  const io::LaserLog plain = SyntheticLog(300, 0.4);
  io::LaserLog log = plain;
  const LogFaultSummary summary = PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kJump, 3.01, 0.2, 0.8}});
  const std::vector<Pose2> before = RobotPoses(plain), after = RobotPoses(log);
  const Pose2& d = summary.faults[0].displacement;
  EXPECT_GT(std::hypot(d.x, d.y), 0.5);
  // The stretch (3.01 .. 3.21 m) ends within the step to pose 65 (3.20 .. 3.25 m).
  for (std::size_t k = 65; k < before.size(); ++k) {
    ExpectNear(after[k], Compose(d, before[k]), 1e-9, "displaced");
    if (k > 65) ExpectNear(Between(after[k - 1], after[k]), Between(before[k - 1], before[k]), 1e-9, "step");
  }
}

// Faults add up: a jump undone by the opposite jump further on leaves the path beyond both as it was.
TEST(PlantLogFaults, SeveralFaultsAddTheirEffects) {
  const io::LaserLog plain = SyntheticLog(200);
  io::LaserLog log = plain;
  const LogFaultSummary summary = PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kJump, 1.0, 0.1, 0.5},
                                                       OdometryFault{OdometryFaultKind::kJump, 4.0, 0.1, -0.5}});
  ASSERT_EQ(summary.faults.size(), 2u);
  EXPECT_NEAR(summary.faults[0].shift_m, 0.5, 1e-9);
  EXPECT_NEAR(summary.faults[1].shift_m, 0.0, 1e-9);
  const std::vector<Pose2> before = RobotPoses(plain), after = RobotPoses(log);
  ExpectNear(after[60], Pose2{before[60].x + 0.5, before[60].y, 0.0}, 1e-9, "between the two");
  ExpectNear(after.back(), before.back(), 1e-9, "after both");
}

// A CARMEN log is followed in file order, even where its timestamps step back; a ROS recording
// (or a log without lines) in time order.
TEST(PlantLogFaults, FollowsFileOrderInACarmenLogAndTimeOrderInARecording) {
  io::LaserLog plain = SyntheticLog(100);
  plain.scans[10].ipc_time -= 0.5;  // a scan stamped before the three records before it
  io::LaserLog log = plain;
  const LogFaultSummary by_file = PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kJump, 3.0, 0.1, 1.0}});
  EXPECT_EQ(by_file.order, "file order");
  EXPECT_NEAR(by_file.travel_m, 99 * kStep, 1e-9);
  io::LaserLog recording = plain;
  recording.recording.emplace();
  const LogFaultSummary by_time = PlantLogFaults(recording, {OdometryFault{OdometryFaultKind::kJump, 3.0, 0.1, 1.0}});
  EXPECT_EQ(by_time.order, "time order");
  EXPECT_GT(by_time.travel_m, 99 * kStep + 0.1);  // the out-of-order scan is a step back and forth
}

TEST(PlantLogFaults, RefusesAStretchBeyondTheTravelAndLogsWithoutAPath) {
  io::LaserLog log = SyntheticLog(100);  // 4.95 m
  const io::LaserLog plain = log;
  try {
    PlantLogFaults(log, {OdometryFault{OdometryFaultKind::kJump, 1.0, 0.1, 1.0},
                         OdometryFault{OdometryFaultKind::kReverse, 4.0, 1.0}});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("fault 2 (reverse at 4 m over 1 m"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("ends at 5 m, beyond the log's odometric travel of 4.95 m"));
  }
  EXPECT_EQ(RobotPoses(log), RobotPoses(plain)) << "nothing changed";
  EXPECT_THROW(PlantLogFaults(log, {(OdometryFault{OdometryFaultKind::kSpin, 1.0, 0.0, 1.0})}), InputError);
  io::LaserLog single = SyntheticLog(1);
  try {
    PlantLogFaults(single, {OdometryFault{OdometryFaultKind::kJump, 0.0, 0.1, 1.0}});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("1 robot poses"));
  }
}

}  // namespace
}  // namespace slamtune::sim
