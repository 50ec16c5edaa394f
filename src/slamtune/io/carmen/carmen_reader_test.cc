#include "slamtune/io/carmen/carmen_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/carmen/carmen_records.h"

namespace slamtune::io {
namespace {

using slamtune::testing::TempFilePath;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// "FLASER n r..r x y theta ox oy otheta ipc host logger" with all readings equal to `reading`.
std::string Flaser(int n, double reading, const Pose2& laser, const Pose2& robot, double t) {
  std::ostringstream out;
  out << "FLASER " << n;
  for (int i = 0; i < n; ++i) out << ' ' << reading;
  out << ' ' << laser.x << ' ' << laser.y << ' ' << laser.theta << ' ' << robot.x << ' ' << robot.y << ' '
      << robot.theta << ' ' << t << " nohost " << t + 0.001 << '\n';
  return out.str();
}

std::string Flaser(double t, double reading = 2.5) { return Flaser(180, reading, {1, 2, 0.5}, {1, 2, 0.5}, t); }

LaserLog ReadText(const std::string& text, const LogReadOptions& options = {}) {
  std::istringstream in(text);
  return ReadCarmenLog(in, "mem.clf", options);
}

// The message of the InputError reading `text` as a log throws.
std::string ReadError(const std::string& text, const LogReadOptions& options = {}) {
  return slamtune::testing::ErrorMessageOf([&] { ReadText(text, options); });
}

std::string WriteGzip(const std::string& name, const std::string& text) {
  const std::string path = TempFilePath("carmen_test", name);
  gzFile gz = gzopen(path.c_str(), "wb9");
  EXPECT_NE(gz, nullptr);
  EXPECT_EQ(gzwrite(gz, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  EXPECT_EQ(gzclose(gz), Z_OK);
  return path;
}

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(CarmenReaderTest, FlaserFieldsAndGeometry) {
  const std::string text = "# header\n" + Flaser(180, 3.0, {1.5, -2.0, 0.25}, {1.0, -2.0, 0.25}, 100.5);
  const LaserLog log = ReadText(text);
  ASSERT_EQ(log.scans.size(), 1u);
  const LaserScanRecord& s = log.scans[0];
  EXPECT_EQ(s.kind, RecordKind::kFlaser);
  EXPECT_EQ(s.line, 2u);
  EXPECT_EQ(s.ranges.size(), 180u);
  EXPECT_EQ(s.ranges[17], 3.0);
  EXPECT_DOUBLE_EQ(s.angle_min, -kPi / 2);
  EXPECT_DOUBLE_EQ(s.angle_increment, DegToRad(1.0));
  EXPECT_EQ(s.laser_pose, (Pose2{1.5, -2.0, 0.25}));
  EXPECT_EQ(s.robot_pose, (Pose2{1.0, -2.0, 0.25}));
  // Offset in the robot frame (heading 0.25): the laser 0.5 m ahead along world x.
  EXPECT_NEAR(s.laser_offset.x, 0.5 * std::cos(0.25), 1e-12);
  EXPECT_NEAR(s.laser_offset.y, -0.5 * std::sin(0.25), 1e-12);
  EXPECT_NEAR(s.laser_offset.theta, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.ipc_time, 100.5);
  EXPECT_DOUBLE_EQ(s.logger_time, 100.501);
  EXPECT_EQ(log.record_counts.at("FLASER"), 1u);
  EXPECT_EQ(log.record_counts.at("#"), 1u);
}

TEST(CarmenReaderTest, FlaserBeamGeometryRule) {
  double min = 0, inc = 0;
  FlaserBeamGeometry(180, &min, &inc);
  EXPECT_DOUBLE_EQ(min, DegToRad(-90));
  EXPECT_DOUBLE_EQ(min + 179 * inc, DegToRad(89));
  FlaserBeamGeometry(361, &min, &inc);
  EXPECT_DOUBLE_EQ(inc, DegToRad(0.5));
  EXPECT_NEAR(min + 360 * inc, DegToRad(90), 1e-12);
  FlaserBeamGeometry(181, &min, &inc);
  EXPECT_DOUBLE_EQ(inc, DegToRad(1.0));
  FlaserBeamGeometry(360, &min, &inc);
  EXPECT_DOUBLE_EQ(inc, DegToRad(0.5));
  FlaserBeamGeometry(1, &min, &inc);
  EXPECT_EQ(inc, 0.0);
  EXPECT_EQ(ReadText(Flaser(361, 1.0, {}, {}, 1.0)).scans[0].angle_increment, DegToRad(0.5));
}

TEST(CarmenReaderTest, RobotLaser1KeepsItsGeometryAndMaxRange) {
  // start -1.5 rad, fov 3, res 1.0, max_range 30, 4 readings, 2 remissions.
  const std::string line =
      "ROBOTLASER1 0 -1.5 3.0 1.0 30.0 0.01 0 4 1.0 2.0 30.0 nan 2 0.5 0.6 "
      "2.1 3.0 1.5707963 2.0 3.0 1.5707963 0.3 0.1 0.5 0.2 0 55.25 host 55.3\n";
  const LaserLog log = ReadText(line);
  ASSERT_EQ(log.scans.size(), 1u);
  const LaserScanRecord& s = log.scans[0];
  EXPECT_EQ(s.kind, RecordKind::kRobotLaser1);
  EXPECT_EQ(s.angle_min, -1.5);
  EXPECT_EQ(s.angle_increment, 1.0);
  EXPECT_EQ(s.max_range, 30.0);
  EXPECT_EQ(s.ranges.size(), 4u);
  EXPECT_TRUE(std::isnan(s.ranges[3]));
  EXPECT_EQ(s.no_returns, 2u);  // 30.0 and nan
  EXPECT_EQ(s.laser_pose, (Pose2{2.1, 3.0, 1.5707963}));
  EXPECT_EQ(s.robot_pose, (Pose2{2.0, 3.0, 1.5707963}));
  // Robot heading pi/2, laser 0.1 m further along world x: 0.1 m to the robot's right.
  EXPECT_NEAR(s.laser_offset.x, 0.0, 1e-7);
  EXPECT_NEAR(s.laser_offset.y, -0.1, 1e-7);
  EXPECT_EQ(s.ipc_time, 55.25);
  EXPECT_EQ(log.no_return_value, 30.0);
  EXPECT_EQ(log.no_return_rule, "ROBOTLASER1 max_range");
}

TEST(CarmenReaderTest, RawLaserPoseInterpolatedFromOdometryWithParamOffset) {
  const std::string text =
      "PARAM robot_frontlaser_offset 0.2 nohost 0\n"
      "PARAM robot_frontlaser_angular_offset 0.1 nohost 0\n"
      "ODOM 0 0 0 0 0 0 10.0 nohost 10.0\n"
      "RAWLASER1 0 -1.5 3.0 1.0 20.0 0.01 0 4 1 2 3 4 0 10.5 nohost 10.5\n"
      "ODOM 2 4 1.0 0 0 0 11.0 nohost 11.0\n"
      "RAWLASER1 0 -1.5 3.0 1.0 20.0 0.01 0 4 1 2 3 4 0 10.75 nohost 10.75\n";
  const LaserLog log = ReadText(text);
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.scans_without_odometry, 0u);
  EXPECT_EQ(log.scans[0].kind, RecordKind::kRawLaser);
  const Pose2 robot = log.scans[0].robot_pose;
  EXPECT_NEAR(robot.x, 1.0, 1e-12);
  EXPECT_NEAR(robot.y, 2.0, 1e-12);
  EXPECT_NEAR(robot.theta, 0.5, 1e-12);
  EXPECT_EQ(log.scans[0].laser_offset, (Pose2{0.2, 0.0, 0.1}));
  const Pose2 laser = log.scans[0].laser_pose;
  EXPECT_NEAR(laser.x, 1.0 + 0.2 * std::cos(0.5), 1e-12);
  EXPECT_NEAR(laser.y, 2.0 + 0.2 * std::sin(0.5), 1e-12);
  EXPECT_NEAR(laser.theta, 0.6, 1e-12);
  EXPECT_EQ(log.no_return_rule, "RAWLASER1 max_range");
  EXPECT_EQ(log.record_counts.at("RAWLASER1"), 2u);
}

TEST(CarmenReaderTest, RawLaserHeadingInterpolatesAcrossPi) {
  const std::string text =
      "ODOM 0 0 3.0 0 0 0 1.0 h 1.0\nODOM 0 0 -3.0 0 0 0 2.0 h 2.0\n"
      "RAWLASER2 0 -1.5 3.0 1.0 20.0 0.01 0 1 1 0 1.5 h 1.5\n";
  const LaserLog log = ReadText(text);
  // Shorter arc from 3.0 to -3.0 passes through pi: halfway is +-pi.
  EXPECT_NEAR(std::fabs(log.scans[0].robot_pose.theta), kPi, 1e-12);
}

TEST(CarmenReaderTest, RawLaserWithoutOdometryIsAnError) {
  EXPECT_EQ(ReadError("RAWLASER1 0 -1.5 1.0 1.0 20.0 0.01 0 2 1 2 0 10.5 nohost 10.5\n"),
            "mem.clf: RAWLASER scans carry no pose and the log has no ODOM record to interpolate one from");
}

TEST(CarmenReaderTest, RawLaserScansOutsideTheOdometrySpanAreCountedNotClamped) {
  const std::string raw = "RAWLASER1 0 -1.5 3.0 1.0 20.0 0.01 0 4 1 2 3 4 0 ";
  std::string text =
      raw + "9.5 h 9.5\nODOM 0 0 0 0 0 0 10.0 h 10\n" + raw + "10.5 h 10.5\nODOM 1 0 0 0 0 0 11.0 h 11\n";
  for (int k = 0; k < 297; ++k) text += raw + std::to_string(12 + k) + " h 1\n";  // the log's ODOM stopped
  const LaserLog log = ReadText(text);
  ASSERT_EQ(log.scans.size(), 1u);
  EXPECT_EQ(log.scans[0].ipc_time, 10.5);
  EXPECT_EQ(log.scans_without_odometry, 298u);
  EXPECT_EQ(log.first_scan_without_odometry, "line 1 at 9.5 s; ODOM 10 .. 11 s");
  EXPECT_EQ(log.record_counts.at("RAWLASER1"), 299u);
}

TEST(CarmenReaderTest, NoRawLaserScanWithinTheOdometrySpanIsAnError) {
  const std::string raw = "RAWLASER1 0 -1.5 3.0 1.0 20.0 0.01 0 4 1 2 3 4 0 ";
  EXPECT_EQ(ReadError("ODOM 0 0 0 0 0 0 10.0 h 10\n" + raw + "12 h 12\n" + raw + "13 h 13\n"),
            "mem.clf: none of the 2 RAWLASER scans lies within the time span of the ODOM records, so none can be "
            "posed (first: line 2 at 12 s; ODOM 10 .. 10 s)");
}

TEST(CarmenReaderTest, ByteOrderMarkDoesNotDropTheFirstScan) {
  const LaserLog log = ReadText("\xEF\xBB\xBF" + Flaser(1.0) + Flaser(2.0));
  EXPECT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.record_counts.at("FLASER"), 2u);
  EXPECT_EQ(log.unknown_records, 0u);
}

// ROBOTLASER1 with 181 readings: "ROBOTLASER1 0 START FOV RES 30 0.01 0 181 r.. 0 poses..".
std::string RobotLaser181(const std::string& start, const std::string& fov, const std::string& res) {
  std::string line = "ROBOTLASER1 0 " + start + " " + fov + " " + res + " 30 0.01 0 181";
  for (int i = 0; i < 181; ++i) line += " 2.5";
  return line + " 0 0 0 0 0 0 0 0 0 0 0 0 1.5 h 1.5\n";
}

TEST(CarmenReaderTest, RobotLaserAnglesInDegreesAreRefusedNamingTheField) {
  EXPECT_EQ(ReadError(RobotLaser181("-90", "180", "1")),
            "mem.clf:1: ROBOTLASER1 start_angle (field 3) -90 is beyond +-2pi: angles must be radians (written in "
            "degrees?)");
  EXPECT_EQ(ReadError("# header\n" + RobotLaser181("-1.570796", "100", "0.017453")),
            "mem.clf:2: ROBOTLASER1 fov (field 4) 100 (5730 deg) is more than a full turn: angles must be radians "
            "(written in degrees?)");
  EXPECT_EQ(ReadError(RobotLaser181("-1.570796", "3.141593", "1")),
            "mem.clf:1: ROBOTLASER1 angular_res (field 5): 181 beams 1 rad apart span 180 rad (10313 deg), more "
            "than a full turn: angles must be radians (written in degrees?)");
}

TEST(CarmenReaderTest, RobotLaserFovThatContradictsTheStepsIsRefused) {
  EXPECT_EQ(ReadError(RobotLaser181("-1.570796", "3.141593", "0.008727")),
            "mem.clf:1: ROBOTLASER1 fov (field 4) 3.141593 rad contradicts 181 readings at angular_res 0.008727 rad "
            "(they span 1.570860 rad)");
  // (n - 1) and n steps both match a fov of pi: 181 and 180 readings at 1 degree.
  EXPECT_EQ(ReadText(RobotLaser181("-1.570796", "3.141593", "0.017453")).scans.size(), 1u);
  LogReadOptions lenient;
  lenient.lenient = true;
  const LaserLog log =
      ReadText(RobotLaser181("-1.570796", "3.141593", "0.017453") + RobotLaser181("-90", "180", "1"), lenient);
  EXPECT_EQ(log.scans.size(), 1u);
  EXPECT_EQ(log.skipped_records, 1u);
}

TEST(CarmenReaderTest, MaxScansStillReadsTheOdometryThatPlacesRawScans) {
  const std::string raw = "RAWLASER1 0 -1.5 3.0 1.0 20.0 0.01 0 1 1 0 ";
  const std::string text = "ODOM 0 0 0 0 0 0 1.0 h 1\n" + raw + "1.5 h 1.5\n" + raw + "1.7 h 1.7\n" +
                           "ODOM 4 0 0 0 0 0 2.0 h 2\n" + "ODOM 8 0 0 0 0 0 3.0 h 3\n";
  LogReadOptions options;
  options.max_scans = 1;
  const LaserLog log = ReadText(text, options);
  ASSERT_EQ(log.scans.size(), 1u);
  EXPECT_TRUE(log.stopped_at_max_scans);
  EXPECT_NEAR(log.scans[0].robot_pose.x, 2.0, 1e-12);
  EXPECT_EQ(log.odometry.size(), 2u);  // stopped at the first ODOM after the scan
}

TEST(CarmenReaderTest, OdomParamCommentsEmptyAndUnknownRecords) {
  const std::string text =
      "# comment\n\n   \nPARAM robot_use_laser on nohost 0\nPARAM some_name two words nohost 0\n"
      "ODOM 1 2 0.5 0.3 0.1 0.0 10.0 nohost 10.01\nTRUEPOS 1 2 3 4 5 6 1 h 1\nSYNC tag 1 h 1\n"
      "NMEA-GGA 1 2 3\n" +
      Flaser(10.5);
  const LaserLog log = ReadText(text);
  EXPECT_EQ(log.scans.size(), 1u);
  ASSERT_EQ(log.odometry.size(), 1u);
  EXPECT_EQ(log.odometry[0].pose, (Pose2{1, 2, 0.5}));
  EXPECT_EQ(log.odometry[0].tv, 0.3);
  EXPECT_EQ(log.odometry[0].rv, 0.1);
  EXPECT_EQ(log.odometry[0].ipc_time, 10.0);
  EXPECT_EQ(log.odometry[0].line, 6u);
  EXPECT_EQ(log.params.at("robot_use_laser"), "on");
  EXPECT_EQ(log.params.at("some_name"), "two words");
  EXPECT_EQ(log.unknown_records, 3u);
  EXPECT_EQ(log.record_counts.at("TRUEPOS"), 1u);
  EXPECT_EQ(log.record_counts.at("NMEA-GGA"), 1u);
  EXPECT_EQ(log.record_counts.at("PARAM"), 2u);
  EXPECT_EQ(log.lines_read, 10u);
}

// The newer CARMEN PARAM form carries ipc_timestamp, hostname and logger_timestamp.
TEST(CarmenReaderTest, ParamsInTheNewerFormatWithBothTimestamps) {
  const std::string text =
      "PARAM laser_front_laser_max_range 2.5 1031745824.648210 nohost 0.001234\n"
      "PARAM robot_frontlaser_offset 0.2 1031745824.648210 nohost 0.001234\n"
      "PARAM some_name two words 1031745824.648210 nohost 0.001234\n"
      "PARAM older_form 0.5 0.6 nohost 0\n" +
      Flaser(10.5);
  const LaserLog log = ReadText(text);
  EXPECT_EQ(log.params.at("laser_front_laser_max_range"), "2.5");
  EXPECT_EQ(log.no_return_rule, "PARAM laser_front_laser_max_range");
  EXPECT_EQ(log.no_return_value, 2.5);
  EXPECT_EQ(log.params.at("robot_frontlaser_offset"), "0.2");
  EXPECT_EQ(log.params.at("some_name"), "two words");
  EXPECT_EQ(log.params.at("older_form"), "0.5 0.6");
}

TEST(CarmenReaderTest, TimeOrderAnomaliesAreCountedAndFileOrderKept) {
  const LaserLog log = ReadText(Flaser(10.0) + Flaser(11.0) + Flaser(10.25) + Flaser(12.0) + Flaser(11.9));
  EXPECT_EQ(log.time_backward_steps, 2u);
  EXPECT_DOUBLE_EQ(log.largest_backward_step_s, 0.75);
  EXPECT_EQ(log.scans[2].ipc_time, 10.25);
}

TEST(CarmenReaderTest, NoReturnsCountedPerScanAndLog) {
  // Frequent maximum 40 (rule 4); NaN, inf, negative and 40 are no-returns.
  std::string line = "FLASER 6 1.0 40 nan inf -1 2.0 0 0 0 0 0 0 5.0 h 5.0\n";
  const LaserLog log = ReadText(line + Flaser(6.0, 40.0));
  EXPECT_EQ(log.no_return_value, 40.0);
  EXPECT_EQ(log.no_return_rule, "maximum reading cluster");
  EXPECT_EQ(log.scans[0].no_returns, 4u);
  EXPECT_EQ(log.scans[0].max_range, 40.0);
  EXPECT_EQ(log.scans[1].no_returns, 180u);
  EXPECT_EQ(log.total_no_returns, 184u);
  EXPECT_EQ(log.total_readings, 186u);
  EXPECT_TRUE(std::isnan(log.scans[0].ranges[2]));  // kept as recorded
}

TEST(CarmenReaderTest, NoReturnPrecedence) {
  // A single 5.0 among 3600 readings is no cluster: rule "none".
  std::string text;
  for (int i = 0; i < 19; ++i) text += Flaser(i, 1.0);
  text += "FLASER 180 5.0";
  for (int i = 1; i < 180; ++i) text += " 1.0";
  text += " 0 0 0 0 0 0 19 h 19\n";
  const LaserLog none = ReadText(text);
  EXPECT_EQ(none.no_return_rule, "none");
  EXPECT_TRUE(std::isinf(none.no_return_value));
  EXPECT_EQ(none.total_no_returns, 0u);
  // A PARAM wins over detection; --no-return wins over the PARAM.
  const std::string with_param = "PARAM laser_front_laser_max_range 2.5 nohost 0\n" + text;
  const LaserLog param = ReadText(with_param);
  EXPECT_EQ(param.no_return_rule, "PARAM laser_front_laser_max_range");
  EXPECT_EQ(param.no_return_value, 2.5);
  EXPECT_EQ(param.scans[19].no_returns, 1u);
  EXPECT_EQ(param.scans[0].max_range, 2.5);
  // A rear-laser PARAM does not count.
  EXPECT_EQ(ReadText("PARAM laser_rear_laser_max_range 2.5 nohost 0\n" + text).no_return_rule, "none");
  LogReadOptions options;
  options.no_return_value = 1.0;
  const LaserLog forced = ReadText(with_param, options);
  EXPECT_EQ(forced.no_return_rule, "--no-return");
  EXPECT_EQ(forced.total_no_returns, 3600u);  // 1.0 >= 1.0
  options.no_return_value = -1;
  EXPECT_EQ(ReadError(text, options),
            "no_return_value = -1: must be 0 (detect from the log) or a positive finite range in metres");
}

TEST(CarmenReaderTest, WrongReadingCountMessage) {
  std::string bad = Flaser(2.0);
  bad.replace(bad.find(" 2.5"), 4, "");  // drop one reading
  EXPECT_EQ(ReadError(Flaser(1.0) + "# c\n" + bad),
            "mem.clf:3: FLASER declares 180 readings but has 179 numbers before the pose");
  EXPECT_EQ(ReadError("FLASER 3 1 2 0 0 0 0 0 0 1 h 1\n"),
            "mem.clf:1: FLASER declares 3 readings but has 2 numbers before the pose");
  EXPECT_EQ(ReadError("FLASER 3 1 2 3 0 0 0\n"),
            "mem.clf:1: FLASER declares 3 readings but the line has only 6 fields after the count (12 needed)");
  EXPECT_EQ(ReadError("FLASER 0 0 0 0 0 0 0 1 h 1\n"), "mem.clf:1: FLASER declares 0 readings");
  EXPECT_EQ(ReadError("FLASER x\n"), "mem.clf:1: FLASER num_readings (field 2) is not a count: 'x'");
}

TEST(CarmenReaderTest, NonNumberAndNonFiniteFields) {
  EXPECT_EQ(ReadError("FLASER 2 1.0 abc 0 0 0 0 0 0 1 h 1\n"),
            "mem.clf:1: FLASER reading 2 (field 4) is not a number: 'abc'");
  EXPECT_EQ(ReadError("FLASER 2 1.0 2.0 0 nan 0 0 0 0 1 h 1\n"), "mem.clf:1: FLASER y (field 6) is not finite: nan");
  EXPECT_EQ(ReadError("FLASER 2 1.0 2.0 0 0 0 0 0 0 inf h 1\n"),
            "mem.clf:1: FLASER ipc_timestamp (field 11) is not finite: inf");
  EXPECT_EQ(ReadError("ODOM 1 2 3 0 0 0 1 h\n"),
            "mem.clf:1: ODOM has 9 fields, expects 10 (ODOM x y theta tv rv accel ipc_timestamp ipc_hostname "
            "logger_timestamp)");
  EXPECT_EQ(ReadError("ODOM 1 2 x 0 0 0 1 h 1\n"), "mem.clf:1: ODOM theta (field 4) is not a number: 'x'");
  EXPECT_EQ(ReadError("ODOM 1 2 8.8e125 0 0 0 1 h 1\n"),
            "mem.clf:1: ODOM theta (field 4) is not a heading in radians: 8.8e125 (|theta| must be <= 1e6)");
  EXPECT_EQ(ReadError("FLASER 2 1.0 2.0 0 0 -2e6 0 0 0 1 h 1\n"),
            "mem.clf:1: FLASER theta (field 7) is not a heading in radians: -2e6 (|theta| must be <= 1e6)");
  EXPECT_EQ(ReadError("PARAM a b\n"),
            "mem.clf:1: PARAM has 3 fields, expects at least 5 (PARAM name value ipc_hostname timestamp)");
  EXPECT_EQ(ReadError("PARAM laser_max_range big h 0\n" + Flaser(1)),
            "mem.clf:1: PARAM laser_max_range value 'big' is not a finite number");
  EXPECT_EQ(ReadError("ROBOTLASER1 0 -1.5 3.0 1.0 30.0 0.01 0 4 1.0 2.0 3.0 4.0 0 0 0 0 0 0 0 0 0 0 0 0 1 h 1 9\n"),
            "mem.clf:1: ROBOTLASER1 declares 4 readings and 0 remissions, so expects 28 fields, but has 29");
  EXPECT_EQ(ReadError("ROBOTLASER1 0 -1.5 3.0 1.0 30.0 0.01 0 4 1.0 2.0 3.0 2 0.5 0 0 0 0 0 0 0 0 0 0 0 1 h 1\n"),
            "mem.clf:1: ROBOTLASER1 declares 4 readings but field 14 after them is not a remission count: '0.5'");
  EXPECT_EQ(ReadError("ROBOTLASER1 0 -1.5 3.0 1.0 -3 0.01 0 1 1.0 0 0 0 0 0 0 0 0 0 0 0 0 1 h 1\n"),
            "mem.clf:1: ROBOTLASER1 max_range (field 6) must be positive: -3");
}

TEST(CarmenReaderTest, TruncatedLastLineIsNamed) {
  std::string text = Flaser(1.0) + Flaser(2.0);
  text.resize(text.size() - 40);  // cut inside the readings, no final newline
  EXPECT_THAT([&] { ReadText(text); },
              ThrowsMessage<InputError>(
                  HasSubstr("mem.clf:2: truncated last line (no newline at the end): FLASER declares 180")));
  // A complete last line without a newline is fine.
  std::string unterminated = Flaser(1.0);
  unterminated.pop_back();
  EXPECT_EQ(ReadText(unterminated).scans.size(), 1u);
}

TEST(CarmenReaderTest, LenientSkipsAndCountsMalformedRecords) {
  const std::string text = Flaser(1.0) + "FLASER 2 1.0 abc 0 0 0 0 0 0 1 h 1\n" + Flaser(2.0) + "ODOM 1 2\n";
  EXPECT_THAT([&] { ReadText(text); }, ThrowsMessage<InputError>(HasSubstr("mem.clf:2:")));
  LogReadOptions options;
  options.lenient = true;
  const LaserLog log = ReadText(text, options);
  EXPECT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.skipped_records, 2u);
  EXPECT_THAT(log.skipped_reasons,
              ElementsAre("2: FLASER reading 2 (field 4) is not a number: 'abc'", HasSubstr("4: ODOM has 3 fields")));
  EXPECT_EQ(log.record_counts.at("FLASER"), 3u);  // skipped ones included
}

TEST(CarmenReaderTest, EmptyOrScanlessInputIsAnError) {
  EXPECT_EQ(ReadError(""), "mem.clf: empty file (no records)");
  EXPECT_EQ(ReadError("\n\n"), "mem.clf: empty file (no records)");
  EXPECT_EQ(ReadError("# only\nODOM 0 0 0 0 0 0 1 h 1\n"),
            "mem.clf: no laser scans (FLASER, ROBOTLASER1 or RAWLASER1..4) in 2 lines");
  LogReadOptions lenient;
  lenient.lenient = true;
  EXPECT_EQ(ReadError("FLASER 1 x 0 0 0 0 0 0 1 h 1\n", lenient),
            "mem.clf: no laser scans (FLASER, ROBOTLASER1 or RAWLASER1..4) in 1 lines (1 skipped as malformed)");
  EXPECT_THAT([] { ReadText("x"); }, ThrowsMessage<InputError>(HasSubstr("no laser scans")));
}

TEST(CarmenReaderTest, UnreadablePathIsAnError) {
  try {
    ReadCarmenLog("/nonexistent/dir/log.clf");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/dir/log.clf: cannot open"));
  }
  EXPECT_THROW(ReadCarmenLog(std::filesystem::temp_directory_path().string()), InputError);
}

TEST(CarmenReaderTest, GzipAndPlainGiveIdenticalScans) {
  std::string text = "PARAM robot_frontlaser_offset 0.0 nohost 0\nODOM 0 0 0 0 0 0 0.5 h 0.5\n";
  for (int i = 0; i < 3000; ++i)
    text += Flaser(180, 1.0 + 0.001 * i, {0.01 * i, 0, 0.001 * i}, {0.01 * i, 0, 0.001 * i}, i);
  const std::string plain = TempFilePath("carmen_test", "plain.clf.gz");  // names do not decide the format
  std::ofstream(plain) << text;
  const std::string gz = WriteGzip("compressed.clf", text);
  const LaserLog a = ReadCarmenLog(plain);
  const LaserLog b = ReadCarmenLog(gz);
  EXPECT_FALSE(a.compressed);
  EXPECT_TRUE(b.compressed);
  ASSERT_EQ(a.scans.size(), 3000u);
  ASSERT_EQ(b.scans.size(), a.scans.size());
  for (std::size_t i = 0; i < a.scans.size(); ++i) {
    ASSERT_EQ(a.scans[i].ranges, b.scans[i].ranges) << i;
    ASSERT_EQ(a.scans[i].laser_pose, b.scans[i].laser_pose) << i;
    ASSERT_EQ(a.scans[i].ipc_time, b.scans[i].ipc_time) << i;
    ASSERT_EQ(a.scans[i].line, b.scans[i].line) << i;
  }
  EXPECT_EQ(a.record_counts, b.record_counts);
  // Concatenated gzip members read as one stream.
  const std::string two = TempFilePath("carmen_test", "two_members.gz");
  std::ofstream(two, std::ios::binary) << ReadBytes(WriteGzip("m1.gz", Flaser(1.0)))
                                       << ReadBytes(WriteGzip("m2.gz", Flaser(2.0)));
  EXPECT_EQ(ReadCarmenLog(two).scans.size(), 2u);
}

TEST(CarmenReaderTest, TruncatedAndCorruptGzipAreErrors) {
  std::string text;
  for (int i = 0; i < 2000; ++i) text += Flaser(180, 1.0 + 0.37 * (i % 13), {}, {}, i);
  const std::string bytes = ReadBytes(WriteGzip("full.gz", text));
  const std::string truncated = TempFilePath("carmen_test", "truncated.gz");
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  try {
    ReadCarmenLog(truncated);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("truncated gzip stream"));
    EXPECT_EQ(e.file(), truncated);
    EXPECT_GT(e.line(), 1u);
  }
  std::string damaged = bytes;
  damaged[damaged.size() - 8] = static_cast<char>(damaged[damaged.size() - 8] ^ 0x55);  // CRC-32 of the trailer
  const std::string corrupt = TempFilePath("carmen_test", "corrupt.gz");
  std::ofstream(corrupt, std::ios::binary) << damaged;
  EXPECT_THROW(
      {
        try {
          ReadCarmenLog(corrupt);
        } catch (const InputError& e) {
          EXPECT_THAT(e.what(), HasSubstr("corrupt gzip stream"));
          throw;
        }
      },
      InputError);
  const std::string trailing = TempFilePath("carmen_test", "trailing.gz");
  std::ofstream(trailing, std::ios::binary) << bytes << "garbage";
  EXPECT_THAT([&] { ReadCarmenLog(trailing); },
              ThrowsMessage<InputError>(HasSubstr("unexpected data after the end of the gzip stream")));
}

TEST(CarmenReaderTest, ReadingIsDeterministic) {
  std::string text;
  for (int i = 0; i < 50; ++i) text += Flaser(i * 0.2, 0.5 + i);
  const LaserLog a = ReadText(text), b = ReadText(text);
  ASSERT_EQ(a.scans.size(), b.scans.size());
  for (std::size_t i = 0; i < a.scans.size(); ++i) EXPECT_EQ(a.scans[i].ranges, b.scans[i].ranges);
  EXPECT_EQ(a.no_return_value, b.no_return_value);
}

}  // namespace
}  // namespace slamtune::io
