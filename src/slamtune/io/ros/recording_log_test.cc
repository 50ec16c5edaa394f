#include "slamtune/io/ros/recording_log.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/common/testing/fixtures.h"
#include "slamtune/io/check/log_check.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/testing/planar_transform.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using slamtune::testing::ErrorMessageOf;
using slamtune::testing::FixturePath;
using testing::Planar;

constexpr std::int64_t kMs = 1000000;

LaserScanMessage ScanMessage(std::int64_t stamp_ns, std::size_t n = 5, const std::string& frame = "laser") {
  LaserScanMessage m;
  m.header.stamp_ns = stamp_ns;
  m.header.frame_id = frame;
  m.angle_min = -0.5f;
  m.angle_increment = 0.25f;
  m.angle_max = -0.5f + 0.25f * static_cast<float>(n - 1);
  m.range_max = 10.0f;
  for (std::size_t i = 0; i < n; ++i) m.ranges.push_back(1.0f + static_cast<float>(i));
  return m;
}

// A robot driving along x at 1 m/s, tf at 20 Hz from t = 0 to 2 s, a laser 0.2 m ahead turned
// by 0.1 rad, and scans at 5 Hz from 0.1 s.
RecordingContents Drive() {
  RecordingContents c;
  c.path = "drive.mcap";
  c.container.topics = {{"/scan", "sensor_msgs/msg/LaserScan", MessageSerialization::kCdr, false, 0},
                        {"/tf", "tf2_msgs/msg/TFMessage", MessageSerialization::kCdr, false, 0},
                        {"/tf_static", "tf2_msgs/msg/TFMessage", MessageSerialization::kCdr, true, 0}};
  for (int k = 0; k <= 40; ++k) c.tf.Add("odom", "base_footprint", k * 50 * kMs, Planar(0.05 * k, 0, 0), false);
  c.tf.Add("base_footprint", "laser", 0, Planar(0.2, 0, 0.1, 0.3), true);
  for (int k = 0; k < 9; ++k) c.scans["/scan"].push_back({ScanMessage(100 * kMs + k * 200 * kMs), 0, "byte 0"});
  return c;
}

TEST(RecordingToLog, ScansArePosedFromTfAtTheirStampsWithTheOffsetFoldedIn) {
  const LaserLog log = RecordingToLog(Drive(), {});
  ASSERT_EQ(log.scans.size(), 9u);
  const RecordingInfo& info = *log.recording;
  EXPECT_EQ(info.scan_topic, "/scan");
  EXPECT_EQ(info.scan_topic_rule, "the only LaserScan topic");
  EXPECT_EQ(info.base_frame, "base_footprint");
  EXPECT_EQ(info.odometry_source, "tf odom -> base_footprint");
  EXPECT_NEAR(info.laser_offset.x, 0.2, 1e-15);
  EXPECT_NEAR(info.laser_offset.theta, 0.1, 1e-15);
  EXPECT_NEAR(info.laser_height_m, 0.3, 1e-15);
  EXPECT_FALSE(info.upside_down);
  const LaserScanRecord& s = log.scans[2];  // at 0.5 s: robot at x = 0.5
  EXPECT_EQ(s.kind, RecordKind::kRosLaserScan);
  EXPECT_DOUBLE_EQ(s.ipc_time, 0.5);
  EXPECT_NEAR(s.robot_pose.x, 0.5, 1e-12);
  EXPECT_NEAR(s.laser_pose.x, 0.7, 1e-12);
  EXPECT_NEAR(s.laser_pose.theta, 0.1, 1e-12);
  EXPECT_EQ(s.angle_min, -0.5);
  EXPECT_EQ(s.angle_increment, 0.25);
  EXPECT_EQ(s.max_range, 10.0);
  EXPECT_EQ(s.ranges, (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_EQ(log.no_return_rule, "LaserScan range_max");
}

TEST(RecordingToLog, ScansOutsideTheOdometryOrInAGapAreCountedNotPosed) {
  RecordingContents c = Drive();
  c.scans["/scan"].push_back({ScanMessage(5000 * kMs), 0, "byte 0"});  // after the last tf sample
  const LaserLog log = RecordingToLog(c, {});
  EXPECT_EQ(log.scans.size(), 9u);
  EXPECT_EQ(log.recording->scans_unplaced, 1u);
  EXPECT_THAT(log.recording->unplaced_examples.front(), ::testing::HasSubstr("scan 9 at 5.000000 s"));
  // tf every 50 ms; a scan between two samples is placed unless the samples are farther apart
  // than --max-odom-gap.
  RecordingContents between = Drive();
  between.scans["/scan"].push_back({ScanMessage(125 * kMs), 0, "byte 0"});
  EXPECT_EQ(RecordingToLog(between, {}).scans.size(), 10u);
  LogReadOptions tight;
  tight.recording.max_odom_gap_s = 0.01;
  const LaserLog gapped = RecordingToLog(between, tight);
  EXPECT_EQ(gapped.scans.size(), 9u);  // the other nine fall exactly on samples
  EXPECT_EQ(gapped.recording->scans_unplaced, 1u);
}

TEST(RecordingToLog, UpsideDownLaserHasReversedReadingsOnMirroredBeams) {
  RecordingContents c = Drive();
  RecordingContents flipped;
  flipped.path = c.path;
  flipped.container = c.container;
  flipped.scans = c.scans;
  for (int k = 0; k <= 40; ++k) flipped.tf.Add("odom", "base_footprint", k * 50 * kMs, Planar(0.05 * k, 0, 0), false);
  RigidTransform3 mount = Planar(0.2, 0, 0.1, 0.3);
  mount.rotation = mount.rotation * Eigen::Quaterniond(Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitX()));
  flipped.tf.Add("base_footprint", "laser", 0, mount, true);
  const LaserLog log = RecordingToLog(flipped, {});
  EXPECT_TRUE(log.recording->upside_down);
  EXPECT_NEAR(log.recording->laser_offset.theta, 0.1, 1e-12);
  const LaserScanRecord& s = log.scans.front();
  EXPECT_EQ(s.ranges, (std::vector<double>{5, 4, 3, 2, 1}));
  EXPECT_DOUBLE_EQ(s.angle_min, -(-0.5 + 4 * 0.25));  // first beam at -angle_max
  // Beam j of the upright description points where the reversed reading's beam pointed:
  // laser angle a maps to base angle yaw - a when the laser is rolled by pi.
  for (int j = 0; j < 5; ++j) {
    const double upright = s.angle_min + j * s.angle_increment;
    const double original = -0.5 + (4 - j) * 0.25;
    EXPECT_NEAR(upright, -original, 1e-12);
  }
}

TEST(RecordingToLog, MissingOffsetSaysWhatToDoAndTheOptionSuppliesIt) {
  RecordingContents c = Drive();
  RecordingContents no_static;
  no_static.path = c.path;
  no_static.container = c.container;
  no_static.scans = c.scans;
  for (int k = 0; k <= 40; ++k) no_static.tf.Add("odom", "base_footprint", k * 50 * kMs, Planar(0.05 * k, 0, 0), false);
  try {
    RecordingToLog(no_static, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no laser offset: base_footprint -> laser"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--laser-offset"));
  }
  LogReadOptions o;
  o.recording.laser_offset = Pose2{0.3, 0.0, 0.0};
  const LaserLog log = RecordingToLog(no_static, o);
  EXPECT_EQ(log.recording->laser_offset_source, "--laser-offset");
  EXPECT_NEAR(log.scans[2].laser_pose.x, 0.8, 1e-12);
}

// A loop in the tf tree on the odometry's or the laser offset's frames is refused, naming it:
// tf2 refuses every lookup through a loop, and a pose composed around it would be made up. A
// loop elsewhere in the tree is kept for the reports.
TEST(RecordingToLog, ATfLoopOnTheFramesUsedIsRefusedNamingIt) {
  RecordingContents odometry_loop = Drive();
  odometry_loop.tf.Add("laser", "odom", 0, Planar(0, 0, 0), true);  // odom had no parent: closes a loop
  EXPECT_EQ(ErrorMessageOf([&] { RecordingToLog(odometry_loop, {}); }),
            "drive.mcap: the tf tree has a loop, odom -> base_footprint -> laser -> odom: odom is its own ancestor "
            "(odom -> base_footprint (dynamic), base_footprint -> laser (static), laser -> odom (static)), so the "
            "odometry odom -> base_footprint cannot be found (tf2 refuses every lookup through a loop); one of these "
            "transforms was published the wrong way round");
  EXPECT_THROW(RecordingToLog(odometry_loop, {}), TfLoopError);

  RecordingContents offset_loop = Drive();
  offset_loop.tf = TfBuffer();
  for (int k = 0; k <= 40; ++k) {
    offset_loop.tf.Add("odom", "base_footprint", k * 50 * kMs, Planar(0.05 * k, 0, 0), false);
  }
  offset_loop.tf.Add("mount", "laser", 0, Planar(0.2, 0, 0), true);
  offset_loop.tf.Add("laser", "mount", 0, Planar(-0.2, 0, 0), true);
  EXPECT_THAT(ErrorMessageOf([&] { RecordingToLog(offset_loop, {}); }),
              ::testing::HasSubstr("loop, laser -> mount -> laser: laser is its own ancestor (laser -> mount (static), "
                                   "mount -> laser (static)), so the laser offset base_footprint -> laser cannot be "
                                   "found"));
  LogReadOptions stated;
  stated.recording.laser_offset = Pose2{0.2, 0, 0};  // the tree is not used for the offset
  EXPECT_EQ(RecordingToLog(offset_loop, stated).scans.size(), 9u);

  RecordingContents elsewhere = Drive();
  elsewhere.tf.Add("camera", "arm", 0, Planar(0, 0, 0), true);
  elsewhere.tf.Add("arm", "camera", 0, Planar(0, 0, 0), true);
  const LaserLog log = RecordingToLog(elsewhere, {});
  EXPECT_EQ(log.scans.size(), 9u);
  EXPECT_EQ(log.recording->tf_loops, std::vector<std::string>{"arm -> camera -> arm"});
}

TEST(RecordingToLog, SeveralScanTopicsNeedAChoice) {
  RecordingContents c = Drive();
  c.scans["/scan_rear"] = c.scans["/scan"];
  try {
    RecordingToLog(c, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("2 LaserScan topics: /scan (9 messages), /scan_rear (9 messages)"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--scan-topic"));
  }
  LogReadOptions o;
  o.recording.scan_topic = "/scan_rear";
  EXPECT_EQ(RecordingToLog(c, o).recording->scan_topic_rule, "--scan-topic");
  o.recording.scan_topic = "/nope";
  EXPECT_THROW(RecordingToLog(c, o), InputError);
}

TEST(RecordingToLog, RangesThatDisagreeWithTheAnglesAreAnErrorOrSkippedWhenLenient) {
  RecordingContents c = Drive();
  c.scans["/scan"][3].message.ranges.push_back(7.0f);  // 6 ranges, angles give 5
  try {
    RecordingToLog(c, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("LaserScan has 6 ranges but its angles"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("give 5 beams"));
  }
  LogReadOptions lenient;
  lenient.lenient = true;
  const LaserLog log = RecordingToLog(c, lenient);
  EXPECT_EQ(log.scans.size(), 8u);
  EXPECT_EQ(log.recording->scans_malformed, 1u);
}

// range_max NaN, infinite, 0 or negative: read with no upper limit, counted with the first scan,
// and said with the rule by `info` and `check` (bad_range_max).
TEST(RecordingToLog, AnUnusableRangeMaxIsReadWithNoUpperLimitAndSaid) {
  RecordingContents c = Drive();
  c.scans["/scan"][0].message.range_max = std::numeric_limits<float>::quiet_NaN();
  c.scans["/scan"][2].message.range_max = 0.0f;
  c.scans["/scan"][5].message.range_max = -1.0f;
  c.scans["/scan"][0].message.ranges[1] = 50.0f;  // above every range_max of the others: a range here
  const LaserLog log = RecordingToLog(c, {});
  ASSERT_EQ(log.scans.size(), 9u);
  EXPECT_EQ(log.recording->scans_bad_range_max, 3u);
  EXPECT_EQ(log.recording->bad_range_max_example, "scan 0 at 0.100000 s: range_max nan");
  EXPECT_TRUE(std::isinf(log.scans[0].max_range));
  EXPECT_EQ(log.scans[0].no_returns, 0u);
  EXPECT_EQ(log.no_return_rule, "none: LaserScan range_max is NaN, infinite, 0 or negative");
  EXPECT_THAT(DescribeLogInput(log),
              ::testing::Contains("note: LaserScan range_max is NaN, infinite, 0 or negative in 3 of 9 scans (first: "
                                  "scan 0 at 0.100000 s: range_max nan): " +
                                  std::string(kBadRangeMaxRule)));
  const CheckReport report = CheckRecordingContents(c, {});
  EXPECT_TRUE(report.Has(ProblemKind::kBadRangeMax));
}

// range_min above range_max leaves no reading that can be a range: the scan is malformed (an
// error naming it; skipped and counted with --lenient).
TEST(RecordingToLog, ARangeMinAboveRangeMaxIsMalformed) {
  RecordingContents c = Drive();
  c.scans["/scan"][4].message.range_min = 12.0f;
  EXPECT_THAT(ErrorMessageOf([&] { RecordingToLog(c, {}); }),
              ::testing::HasSubstr("drive.mcap: byte 0: /scan: LaserScan range_min 12 m exceeds range_max 10 m"));
  LogReadOptions lenient;
  lenient.lenient = true;
  const LaserLog log = RecordingToLog(c, lenient);
  EXPECT_EQ(log.scans.size(), 8u);
  EXPECT_EQ(log.recording->scans_malformed, 1u);
}

// Not one reading a range (all inf, NaN, above range_max or at range_min): nothing to map, a
// one-line error for the commands that map; `check` reports it.
TEST(RecordingToLog, ALogWithoutASingleRangeIsRefusedForMapping) {
  RecordingContents c = Drive();
  for (RecordedScan& scan : c.scans["/scan"]) {
    for (std::size_t i = 0; i < scan.message.ranges.size(); ++i) {
      scan.message.ranges[i] = i % 2 == 0 ? std::numeric_limits<float>::infinity() : 10.5f;
    }
  }
  const LaserLog log = RecordingToLog(c, {});
  EXPECT_EQ(CountRanges(log), 0u);
  EXPECT_EQ(ErrorMessageOf([&] { RequireRanges(log); }),
            "drive.mcap: not one of the 45 readings of the 9 scans is a range (each is inf, NaN, negative, at or above "
            "range_max 10 m or at or below range_min): nothing to map");
  const CheckReport report = CheckRecordingContents(c, {});
  EXPECT_TRUE(report.Has(ProblemKind::kNoValidReading));
  // Without a single range there is no largest range to hold against range_max.
  EXPECT_FALSE(report.Has(ProblemKind::kRangeMaxTooHigh));
  c.scans["/scan"][8].message.ranges[1] = 3.0f;
  EXPECT_NO_THROW(RequireRanges(RecordingToLog(c, {})));
  EXPECT_FALSE(CheckRecordingContents(c, {}).Has(ProblemKind::kNoValidReading));
}

TEST(RecordingToLog, A360LaserWhoseLastAngleClosesTheCircleIsAccepted) {
  RecordingContents c = Drive();
  for (RecordedScan& s : c.scans["/scan"]) {
    LaserScanMessage& m = s.message;
    m.ranges.assign(360, 2.0f);
    m.angle_min = 0.0f;
    m.angle_increment = static_cast<float>(kTwoPi / 360.0);
    m.angle_max = static_cast<float>(kTwoPi);  // 361 beams by the angles, 360 readings
  }
  const LaserLog log = RecordingToLog(c, {});
  EXPECT_EQ(log.scans.front().ranges.size(), 360u);
}

TEST(RecordingToLog, AnglesInDegreesAreAnErrorNamingTheMessage) {
  RecordingContents c = Drive();
  LaserScanMessage& m = c.scans["/scan"][2].message;  // 181 beams from -90 to 90 "rad", step 1
  m.ranges.assign(181, 2.0f);
  m.angle_min = -90.0f;
  m.angle_max = 90.0f;
  m.angle_increment = 1.0f;
  c.scans["/scan"][2].location = "byte 4096";
  EXPECT_EQ(ErrorMessageOf([&] { RecordingToLog(c, {}); }),
            "drive.mcap: byte 4096: /scan: LaserScan angles -90 .. 90 rad (step 1) go beyond a full turn: angles "
            "must be radians (written in degrees?) (--lenient skips such scans and counts them)");
}

TEST(RecordingToLog, AFieldOfViewOfMoreThanAFullTurnIsAnError) {
  RecordingContents c = Drive();
  LaserScanMessage& m = c.scans["/scan"][0].message;  // 100 rad = 5729 deg over 5 beams
  m.angle_min = -3.0f;
  m.angle_max = 97.0f;
  m.angle_increment = 25.0f;
  EXPECT_EQ(ErrorMessageOf([&] { RecordingToLog(c, {}); }),
            "drive.mcap: byte 0: /scan: LaserScan angles -3 .. 97 rad (step 25) go beyond a full turn: angles must "
            "be radians (written in degrees?) (--lenient skips such scans and counts them)");
}

TEST(RecordingToLog, OdometryTopicIsInterpolatedLikeTf) {
  RecordingContents c = Drive();
  c.container.topics.push_back({"/odom", "nav_msgs/msg/Odometry", MessageSerialization::kCdr, false, 0});
  for (int k = 0; k <= 10; ++k) {
    OdometrySample s;
    s.stamp_ns = k * 200 * kMs;
    s.frame_id = "odom";
    s.child_frame_id = "base_footprint";
    s.pose = Planar(0.2 * k + 10.0, 0, 0);
    s.linear_x = 1.0;
    c.odometry["/odom"].push_back(s);
  }
  LogReadOptions o;
  o.recording.odom_topic = "/odom";
  const LaserLog log = RecordingToLog(c, o);
  EXPECT_EQ(log.recording->odometry_rule, "--odom-topic");
  EXPECT_NEAR(log.scans[0].robot_pose.x, 10.1, 1e-12);  // 0.1 s: halfway between two samples
  EXPECT_TRUE(log.recording->odometry_velocities);
  EXPECT_EQ(log.odometry.size(), 11u);
  EXPECT_EQ(log.odometry[3].tv, 1.0);
}

TEST(RecordingToLog, WithoutTfOdometryTheOnlyOdometryTopicIsUsedAndSaid) {
  RecordingContents c;
  c.path = "drive.db3";
  c.tf.Add("base_footprint", "laser", 0, Planar(0.2, 0, 0), true);
  for (int k = 0; k < 3; ++k) c.scans["/scan"].push_back({ScanMessage(k * 100 * kMs), 0, "row 1"});
  for (int k = 0; k <= 3; ++k) {
    OdometrySample s;
    s.stamp_ns = k * 100 * kMs;
    s.frame_id = "odom";
    s.child_frame_id = "base_footprint";
    c.odometry["/wheel_odom"].push_back(s);
  }
  const LaserLog log = RecordingToLog(c, {});
  EXPECT_THAT(log.recording->odometry_rule, ::testing::HasSubstr("the only Odometry topic"));
  EXPECT_EQ(log.scans.size(), 3u);
  c.odometry.clear();
  EXPECT_THROW(RecordingToLog(c, {}), InputError);
}

// The fixture recordings (tests/fixtures/recordings): choices, counts and planted faults.
TEST(RecordingFixtures, OdomTopicGivesPosesNearTheTfOnes) {
  LogReadOptions o;
  o.recording.odom_topic = "/odom";  // every second scan stamp (0.67 s apart): the others interpolated
  EXPECT_EQ(ReadLaserLog(FixturePath("recordings/office_slice_none.mcap"), o).scans.size(), 60u);  // 0.5 s gap rule
  o.recording.max_odom_gap_s = 1.0;
  const LaserLog by_topic = ReadLaserLog(FixturePath("recordings/office_slice_none.mcap"), o);
  const LaserLog by_tf = ReadLaserLog(FixturePath("recordings/office_slice_none.mcap"));
  ASSERT_EQ(by_topic.scans.size(), 119u);  // the last scan is after the last Odometry message
  EXPECT_EQ(by_topic.recording->scans_unplaced, 1u);
  for (std::size_t k = 0; k < by_topic.scans.size(); k += 2) {
    EXPECT_NEAR(by_topic.scans[k].laser_pose.x, by_tf.scans[k].laser_pose.x, 1e-12);
  }
  for (std::size_t k = 1; k < by_topic.scans.size(); k += 2) {
    EXPECT_NEAR(by_topic.scans[k].laser_pose.x, by_tf.scans[k].laser_pose.x, 0.15);  // chord of a turn, drift
  }
}

TEST(RecordingFixtures, PlantedFaultsAreReportedByTheReader) {
  try {
    ReadLaserLog(FixturePath("recordings/fault_no_tf_static.mcap"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no laser offset"));
  }
  const LaserLog gap = ReadLaserLog(FixturePath("recordings/fault_tf_gap.mcap"));
  EXPECT_EQ(gap.recording->scans_unplaced, 9u);
  EXPECT_EQ(gap.scans.size(), 111u);
  EXPECT_THROW(ReadLaserLog(FixturePath("recordings/fault_two_scan_topics.mcap")), InputError);
  const LaserLog inf_nan = ReadLaserLog(FixturePath("recordings/fault_inf_nan.mcap"));
  std::size_t non_finite = 0;
  for (const LaserScanRecord& s : inf_nan.scans) {
    for (double r : s.ranges) non_finite += std::isfinite(r) ? 0 : 1;
  }
  EXPECT_EQ(non_finite, 409u + 346u);
}

}  // namespace
TEST(RecordingFiles, EveryScanUndecodableIsAnErrorEvenWhenLenient) {
  // SmallMcap's LaserScan payloads are placeholders ("scan-1", ...) that no decoder reads.
  const std::string path = testing::FreshTempDir("undecodable_scans") + "/small.mcap";
  testing::WriteFile(path, testing::SmallMcap(""));
  LogReadOptions lenient;
  lenient.lenient = true;
  try {
    ReadLaserLog(path, lenient);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("none of the 3 sensor_msgs/LaserScan messages in the recording could "
                                               "be decoded (first: "));
  }
}

}  // namespace slamtune::io
