#include "slamtune/io/carmen/carmen_writer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/io/carmen/carmen_records.h"

namespace slamtune::io {
namespace {

using ::testing::HasSubstr;

LaserScanRecord FlaserRecord(std::size_t n, double time, const Pose2& pose) {
  LaserScanRecord scan;
  scan.kind = RecordKind::kFlaser;
  FlaserBeamGeometry(n, &scan.angle_min, &scan.angle_increment);
  scan.max_range = 30.0;
  // Whole millimetres as k / 1000: the doubles that 3-decimal text parses back to.
  for (std::size_t i = 0; i < n; ++i) scan.ranges.push_back(static_cast<double>(1000 + i * 37 % 1000) / 1000.0);
  scan.laser_pose = scan.robot_pose = pose;
  scan.ipc_time = time;
  scan.logger_time = time - 100.0;
  return scan;
}

OdomRecord Odom(double time, const Pose2& pose) {
  OdomRecord odom;
  odom.pose = pose;
  odom.tv = 0.5;
  odom.rv = -0.25;
  odom.ipc_time = time;
  odom.logger_time = time - 100.0;
  return odom;
}

LaserLog SmallLog() {
  LaserLog log;
  log.params = {{"laser_front_laser_max_range", "30"}, {"robot_frontlaser_offset", "0.0"}};
  log.odometry = {Odom(100.0, Pose2{0, 0, 0}), Odom(100.1, Pose2{0.05, 0.001, 0.002}),
                  Odom(100.2, Pose2{0.1, 0.002, -3.14159})};
  log.scans = {FlaserRecord(181, 100.0, Pose2{0, 0, 0}), FlaserRecord(181, 100.2, Pose2{0.1, 0.002, -3.14159})};
  log.scans[1].ranges[5] = 30.0;  // a no-return
  return log;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(WriteCarmenLog, WritesHeaderParamsAndRecordsInTimeOrder) {
  std::ostringstream out;
  CarmenWriteOptions options;
  options.comments = {"made by a test"};
  const CarmenWriteSummary summary = WriteCarmenLog(out, SmallLog(), options);
  const auto lines = Lines(out.str());
  ASSERT_EQ(lines.size(), summary.lines);
  EXPECT_EQ(summary.params, 2u);
  EXPECT_EQ(summary.odometry, 3u);
  EXPECT_EQ(summary.scans, 2u);
  EXPECT_EQ(summary.robotlaser1, 0u);
  std::size_t first_record = 0;
  while (lines[first_record].rfind("#", 0) == 0) ++first_record;
  EXPECT_EQ(first_record, summary.comments);
  EXPECT_EQ(lines[first_record - 1], "# made by a test");
  EXPECT_EQ(lines[first_record], "PARAM laser_front_laser_max_range 30 slamtune 0");
  // ODOM before FLASER at equal time, then by time.
  EXPECT_EQ(lines[first_record + 2],
            "ODOM 0.000000 0.000000 0.000000 0.500000 -0.250000 0.000000 100.000000 slamtune 0.000000");
  EXPECT_THAT(lines[first_record + 3], ::testing::StartsWith("FLASER 181 1.000 1.037 1.074 "));
  EXPECT_THAT(
      lines[first_record + 3],
      ::testing::EndsWith(" 0.000000 0.000000 0.000000 0.000000 0.000000 0.000000 100.000000 slamtune 0.000000"));
  EXPECT_THAT(lines[first_record + 4], ::testing::StartsWith("ODOM 0.050000 0.001000 0.002000 "));
  EXPECT_THAT(lines[first_record + 5], ::testing::StartsWith("ODOM "));
  EXPECT_THAT(lines[first_record + 6], ::testing::StartsWith("FLASER 181 "));
  EXPECT_EQ(lines.size(), first_record + 7);
}

TEST(WriteCarmenLog, ReadsBackThroughTheReader) {
  const LaserLog log = SmallLog();
  std::ostringstream out;
  WriteCarmenLog(out, log);
  std::istringstream in(out.str());
  const LaserLog back = ReadCarmenLog(in, "written");
  ASSERT_EQ(back.scans.size(), 2u);
  ASSERT_EQ(back.odometry.size(), 3u);
  EXPECT_EQ(back.no_return_rule, "PARAM laser_front_laser_max_range");
  EXPECT_EQ(back.no_return_value, 30.0);
  EXPECT_EQ(back.params, log.params);
  for (std::size_t k = 0; k < 2; ++k) {
    const LaserScanRecord &a = log.scans[k], &b = back.scans[k];
    EXPECT_EQ(b.kind, RecordKind::kFlaser);
    EXPECT_EQ(b.ranges, a.ranges);  // millimetre values survive 3 decimals exactly
    EXPECT_EQ(b.angle_min, a.angle_min);
    EXPECT_EQ(b.angle_increment, a.angle_increment);
    EXPECT_EQ(b.ipc_time, a.ipc_time);
    EXPECT_NEAR(b.laser_pose.theta, a.laser_pose.theta, 5e-7);
    EXPECT_NEAR(b.robot_pose.x, a.robot_pose.x, 5e-7);
  }
  EXPECT_EQ(back.scans[1].no_returns, 1u);
  EXPECT_EQ(back.odometry[1].pose, (Pose2{0.05, 0.001, 0.002}));
  EXPECT_EQ(back.odometry[1].rv, -0.25);
}

TEST(WriteCarmenLog, OtherGeometriesBecomeRobotLaser1AndReadBackExactly) {
  LaserLog log;
  LaserScanRecord scan = FlaserRecord(240, 5.0, Pose2{1, 2, 0.5});
  scan.kind = RecordKind::kRobotLaser1;
  scan.angle_min = -DegToRad(120);
  scan.angle_increment = DegToRad(240) / 239;
  scan.max_range = 5.6;
  scan.laser_pose = Pose2{1.2, 2.0, 0.5};
  log.scans = {scan};
  std::ostringstream out;
  EXPECT_EQ(WriteCarmenLog(out, log).robotlaser1, 1u);
  std::istringstream in(out.str());
  const LaserLog back = ReadCarmenLog(in, "written");
  ASSERT_EQ(back.scans.size(), 1u);
  const LaserScanRecord& b = back.scans[0];
  EXPECT_EQ(b.kind, RecordKind::kRobotLaser1);
  EXPECT_EQ(b.angle_min, scan.angle_min);
  EXPECT_EQ(b.angle_increment, scan.angle_increment);
  EXPECT_EQ(b.max_range, 5.6);
  EXPECT_EQ(b.ranges, scan.ranges);
  EXPECT_EQ(b.laser_pose, scan.laser_pose);
  EXPECT_EQ(b.robot_pose, scan.robot_pose);
}

TEST(WriteCarmenLog, RefusesWhatCarmenCannotCarryAndWritesNothing) {
  LaserLog log = SmallLog();
  log.scans[1].ranges[3] = std::nan("");
  std::ostringstream out;
  EXPECT_THAT([&] { WriteCarmenLog(out, log); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("laser scan 1: reading 3 is nan")));
  EXPECT_TRUE(out.str().empty());

  log = SmallLog();
  log.scans[0].angle_increment = DegToRad(0.5);  // not the FLASER rule for 181 readings
  EXPECT_THAT([&] { WriteCarmenLog(out, log); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("cannot write laser scan 0 as FLASER")));

  log = SmallLog();
  log.params["bad name"] = "1";
  EXPECT_THAT([&] { WriteCarmenLog(out, log); }, ::testing::ThrowsMessage<InputError>(HasSubstr("PARAM 'bad name'")));

  log = SmallLog();
  log.odometry[2].pose.x = INFINITY;
  EXPECT_THAT([&] { WriteCarmenLog(out, log); }, ::testing::ThrowsMessage<InputError>(HasSubstr("ODOM record 2")));
  EXPECT_TRUE(out.str().empty());
}

TEST(CarmenWriteOptions, ValidateNamesFieldValueAndRule) {
  CarmenWriteOptions options;
  options.hostname = "two words";
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("hostname = 'two words': must be one non-empty word")));
  options = CarmenWriteOptions();
  options.range_decimals = 12;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("range_decimals = 12: must be in [0, 9]")));
}

TEST(WriteCarmenLog, UnwritablePathIsAnInputError) {
  EXPECT_THAT([&] { WriteCarmenLog("/nonexistent-folder/x.clf", SmallLog()); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("/nonexistent-folder/x.clf: cannot write")));
}

// Convert makes every scan ROBOTLASER1; fault keeps FLASER scans. Either way non-finite readings
// become the max range, a scan without one gets one above its readings, and the PARAMs carry the
// first scan's offset and max range, so the written log reads back with the same values.
TEST(PrepareForCarmen, MakesAnyLogWritableAndKeepsFlaserOnRequest) {
  LaserLog log = SmallLog();
  log.scans[0].laser_offset = Pose2{0.2, -0.1, 0.05};
  LaserScanRecord ros = FlaserRecord(181, 100.4, Pose2{0.2, 0.0, 0.0});
  ros.kind = RecordKind::kRosLaserScan;
  ros.max_range = std::numeric_limits<double>::infinity();
  ros.ranges[3] = std::numeric_limits<double>::infinity();
  ros.ranges[4] = std::nan("");
  log.scans.push_back(ros);
  LaserLog kept = log;
  EXPECT_EQ(PrepareForCarmen(&log), 2u);
  for (const LaserScanRecord& scan : log.scans) EXPECT_EQ(scan.kind, RecordKind::kRobotLaser1);
  const LaserScanRecord& last = log.scans.back();
  EXPECT_DOUBLE_EQ(last.max_range, 1.999 + 1.0);  // the largest finite reading is 1.999 m
  EXPECT_EQ(last.ranges[3], last.max_range);
  EXPECT_EQ(last.ranges[4], last.max_range);
  EXPECT_EQ(log.params["robot_frontlaser_offset"], "0.2");
  EXPECT_EQ(log.params["robot_frontlaser_side_offset"], "-0.1");
  EXPECT_EQ(log.params["robot_frontlaser_angular_offset"], "0.05");
  EXPECT_EQ(log.params["laser_front_laser_max_range"], "30");
  std::ostringstream converted;
  EXPECT_NO_THROW(WriteCarmenLog(converted, log));

  EXPECT_EQ(PrepareForCarmen(&kept, true), 2u);
  EXPECT_EQ(kept.scans[0].kind, RecordKind::kFlaser);
  EXPECT_EQ(kept.scans[1].kind, RecordKind::kFlaser);
  EXPECT_EQ(kept.scans[2].kind, RecordKind::kRobotLaser1);
  std::ostringstream out;
  const CarmenWriteSummary summary = WriteCarmenLog(out, kept);
  EXPECT_EQ(summary.scans, 3u);
  EXPECT_EQ(summary.robotlaser1, 1u);
}

}  // namespace
}  // namespace slamtune::io
