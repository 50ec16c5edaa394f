#include "slamtune/io/check/log_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/fixtures.h"
#include "slamtune/io/testing/straight_drive_log.h"

namespace slamtune::io {
namespace {

using slamtune::testing::FixturePath;

// 200 scans at 5 Hz of a robot driving along x at 0.5 m/s, ODOM at 10 Hz with its speed;
// readings up to 20 m of a 30 m laser.
LaserLog CleanLog() {
  LaserLog log = testing::StraightDriveLog({.start_s = 100.0, .odometry_records = 400, .scans = 200});
  log.path = "clean.clf";
  for (LaserScanRecord& s : log.scans) {
    s.angle_min = -1.5707963267948966;
    s.angle_increment = 0.017453292519943295;
    s.max_range = 30.0;
    s.ranges.assign(181, 5.0);
    s.ranges[90] = 20.0;
  }
  log.no_return_value = 30.0;
  return log;
}

std::vector<std::string> Kinds(const CheckReport& report) {
  std::vector<std::string> kinds;
  for (const CheckProblem& p : report.problems) kinds.push_back(ProblemKindName(p.kind));
  return kinds;
}

TEST(LogCheck, CleanLogHasNoProblem) {
  const CheckReport report = CheckLog(CleanLog());
  EXPECT_TRUE(report.ok()) << FormatCheckReport(report);
  EXPECT_THAT(FormatCheckReport(report), ::testing::HasSubstr("verdict: no problem found"));
}

struct Planted {
  const char* name;
  ProblemKind kind;
  std::function<void(LaserLog*)> plant;
};

class LogCheckFinds : public ::testing::TestWithParam<Planted> {};

TEST_P(LogCheckFinds, ThePlantedFaultAndNothingElse) {
  LaserLog log = CleanLog();
  GetParam().plant(&log);
  const CheckReport report = CheckLog(log);
  EXPECT_THAT(Kinds(report), ::testing::ElementsAre(ProblemKindName(GetParam().kind))) << FormatCheckReport(report);
}

INSTANTIATE_TEST_SUITE_P(
    Faults, LogCheckFinds,
    ::testing::Values(
        Planted{"ScanGap", ProblemKind::kScanGap,
                [](LaserLog* log) { log->scans.erase(log->scans.begin() + 50, log->scans.begin() + 60); }},
        Planted{"StampBackward", ProblemKind::kScanStampBackward,
                [](LaserLog* log) { std::swap(log->scans[70].ipc_time, log->scans[71].ipc_time); }},
        Planted{"StampDuplicate", ProblemKind::kScanStampDuplicate,
                [](LaserLog* log) { log->scans[80].ipc_time = log->scans[79].ipc_time; }},
        Planted{"BeamChange", ProblemKind::kBeamGeometryChange,
                [](LaserLog* log) { log->scans[90].ranges.pop_back(); }},
        Planted{"RangeMaxTooLow", ProblemKind::kRangeMaxTooLow, [](LaserLog* log) { log->scans[12].ranges[3] = 31.5; }},
        Planted{"RangeMaxTooHigh", ProblemKind::kRangeMaxTooHigh,
                [](LaserLog* log) {
                  for (LaserScanRecord& s : log->scans) s.ranges[90] = 5.0;
                }},
        Planted{"MostlyNoReturns", ProblemKind::kMostlyNoReturns,
                [](LaserLog* log) {
                  for (LaserScanRecord& s : log->scans) s.no_returns = 150;
                }},
        Planted{"OdometryJump", ProblemKind::kOdometryJump,
                [](LaserLog* log) {
                  for (std::size_t k = 200; k < log->odometry.size(); ++k) log->odometry[k].pose.x += 2.0;
                }},
        Planted{"OdometryStallGap", ProblemKind::kOdometryStall,
                [](LaserLog* log) { log->odometry.erase(log->odometry.begin() + 100, log->odometry.begin() + 130); }},
        Planted{"OdometryStallFrozen", ProblemKind::kOdometryStall,
                [](LaserLog* log) {
                  for (std::size_t k = 100; k < log->odometry.size(); ++k)
                    log->odometry[k].pose.x = 5.0 + 0.05 * (k < 130 ? 0 : k - 130);
                }},
        Planted{"HeadingWrap", ProblemKind::kHeadingWrap,
                [](LaserLog* log) {
                  // Headings 0.3 then -2.9 rad, the poses moving along them.
                  for (std::size_t k = 1; k < log->odometry.size(); ++k) {
                    const double heading = k < 150 ? 0.3 : -2.9;
                    const Pose2& before = log->odometry[k - 1].pose;
                    log->odometry[k].pose = {before.x + 0.05 * std::cos(heading), before.y + 0.05 * std::sin(heading),
                                             heading};
                  }
                }},
        Planted{"VelocityMismatch", ProblemKind::kOdometryVelocityMismatch,
                [](LaserLog* log) {
                  // Reversing for 10 s, written by a logger that integrated |tv|: poses move forward.
                  for (std::size_t k = 100; k < 200; ++k) log->odometry[k].tv = -0.5;
                }}),
    [](const ::testing::TestParamInfo<Planted>& info) { return std::string(info.param.name); });

TEST(LogCheck, ProblemsListTheirFirstScansAndTimes) {
  LaserLog log = CleanLog();
  log.scans.erase(log.scans.begin() + 50, log.scans.begin() + 60);
  const CheckReport report = CheckLog(log);
  ASSERT_EQ(report.problems.size(), 1u);
  EXPECT_EQ(report.problems[0].count, 1u);
  EXPECT_EQ(report.problems[0].scans, (std::vector<std::size_t>{50}));
  EXPECT_DOUBLE_EQ(report.problems[0].times_s[0], 100.0 + 0.2 * 60);
  EXPECT_THAT(FormatCheckReport(report), ::testing::HasSubstr("at scan 50 (112.000 s)"));
}

TEST(LogCheck, RecordingFaultsAreFoundInTheFixtureBags) {
  const CheckOptions options;
  EXPECT_TRUE(CheckRecording(FixturePath("recordings/office_zstd.mcap"), {}, options).ok());
  EXPECT_TRUE(
      CheckRecording(FixturePath("recordings/fault_no_tf_static.mcap"), {}, options).Has(ProblemKind::kNoLaserOffset));
  const CheckReport gap = CheckRecording(FixturePath("recordings/fault_tf_gap.mcap"), {}, options);
  EXPECT_TRUE(gap.Has(ProblemKind::kTfMissing));
  EXPECT_TRUE(gap.Has(ProblemKind::kTfLate));
  EXPECT_TRUE(CheckRecording(FixturePath("recordings/fault_two_scan_topics.mcap"), {}, options)
                  .Has(ProblemKind::kSeveralScanTopics));
  EXPECT_TRUE(
      CheckRecording(FixturePath("recordings/fault_inf_nan.mcap"), {}, options).Has(ProblemKind::kRangeMaxTooLow));
}

// A robot driving along x at 0.5 m/s, tf at 20 Hz, a laser at the base and scans at 5 Hz.
RecordingContents DriveContents() {
  constexpr std::int64_t kMs = 1000000;
  RecordingContents c;
  c.path = "drive.bag";
  c.container.topics = {{"/scan", "sensor_msgs/LaserScan", MessageSerialization::kRos1, false, 0},
                        {"/tf", "tf2_msgs/TFMessage", MessageSerialization::kRos1, false, 0}};
  RigidTransform3 pose;
  for (int k = 0; k <= 200; ++k) {
    pose.translation = {0.025 * k, 0.0, 0.0};
    c.tf.Add("odom", "base_link", k * 50 * kMs, pose, false);
  }
  c.tf.Add("base_link", "laser", 0, RigidTransform3{}, true);
  for (int k = 0; k < 45; ++k) {
    LaserScanMessage m;
    m.header.stamp_ns = 100 * kMs + k * 200 * kMs;
    m.header.frame_id = "laser";
    m.angle_min = -1.5f;
    m.angle_increment = 0.5f;
    m.angle_max = 1.5f;
    m.range_max = 10.0f;
    m.ranges = {3.0f, 4.0f, 5.0f, 6.0f, 5.0f, 4.0f, 3.0f};
    c.scans["/scan"].push_back({m, m.header.stamp_ns, "byte 0"});
  }
  return c;
}

// A loop on the frames used ends the check there with the loop as its problem; a loop elsewhere
// is one problem among the rest.
TEST(LogCheck, ATfLoopIsAProblemNamingItsFrames) {
  RecordingContents loop = DriveContents();
  loop.tf.Add("laser", "odom", 0, RigidTransform3{}, true);
  const CheckReport report = CheckRecordingContents(loop, {});
  EXPECT_EQ(Kinds(report), std::vector<std::string>{"tf_loop"});
  EXPECT_THAT(report.problems[0].what,
              ::testing::HasSubstr("the tf tree has a loop, odom -> base_link -> laser -> odom: "
                                   "odom is its own ancestor"));
  EXPECT_THAT(report.facts, ::testing::Contains("topic: /scan (sensor_msgs/LaserScan), 0 messages"));
  EXPECT_THAT(FormatCheckReport(report), ::testing::HasSubstr("verdict: 1 problem: tf_loop"));

  EXPECT_TRUE(CheckRecordingContents(DriveContents(), {}).ok())
      << FormatCheckReport(CheckRecordingContents(DriveContents(), {}));
  RecordingContents elsewhere = DriveContents();
  elsewhere.tf.Add("camera", "arm", 0, RigidTransform3{}, true);
  elsewhere.tf.Add("arm", "camera", 0, RigidTransform3{}, true);
  const CheckReport beside = CheckRecordingContents(elsewhere, {});
  EXPECT_EQ(Kinds(beside), std::vector<std::string>{"tf_loop"});
  EXPECT_THAT(beside.problems[0].what, ::testing::HasSubstr("arm -> camera -> arm (not on the frames used here)"));
}

TEST(LogCheck, OptionsAreValidated) {
  CheckOptions bad;
  bad.gap_factor = 0.5;
  EXPECT_THROW(bad.Validate(), InputError);
}

}  // namespace
}  // namespace slamtune::io
