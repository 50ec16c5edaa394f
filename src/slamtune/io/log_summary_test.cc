#include "slamtune/io/log_summary.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "slamtune/io/carmen/carmen_reader.h"

namespace slamtune::io {
namespace {

using ::testing::HasSubstr;

// The summary of `text` read as a CARMEN log.
LogSummary SummaryOfText(const std::string& text) {
  std::istringstream in(text);
  return SummarizeLog(ReadCarmenLog(in, "mem.clf"));
}

TEST(LogSummaryTest, CountsSpansAndOdometry) {
  // Three FLASER scans (4 readings: 180/4 = 45 deg steps), laser poses (0,0,0) -> (3,4,pi/2) -> (3,4,-pi/2).
  const std::string text =
      "# c\nPARAM a b h 0\nODOM 0 0 0 0 0 0 9.5 h 9.5\n"
      "FLASER 4 1 2 3 50 0 0 0 0 0 0 10.0 h 10.0\n"
      "FLASER 4 1 2 3 50 3 4 1.5707963267948966 3 4 1.5707963267948966 10.5 h 10.5\n"
      "FLASER 4 1 50 0.5 50 3 4 -1.5707963267948966 3 4 -1.5707963267948966 10.25 h 10.25\n"
      "SYNC x 1 h 1\n";
  const LogSummary s = SummaryOfText(text);
  EXPECT_EQ(s.scans, 3u);
  EXPECT_EQ(s.odometry_records, 1u);
  EXPECT_EQ(s.params, 1u);
  EXPECT_EQ(s.record_counts.at("FLASER"), 3u);
  EXPECT_EQ(s.record_counts.at("SYNC"), 1u);
  EXPECT_EQ(s.unknown_records, 1u);
  EXPECT_DOUBLE_EQ(s.first_time_s, 10.0);
  EXPECT_DOUBLE_EQ(s.last_time_s, 10.25);
  EXPECT_DOUBLE_EQ(s.duration_s, 0.25);
  EXPECT_DOUBLE_EQ(s.scan_rate_hz, 8.0);
  EXPECT_EQ(s.readings_per_scan, 4u);
  EXPECT_FALSE(s.readings_per_scan_varies);
  EXPECT_DOUBLE_EQ(s.angle_min_deg, -90.0);
  EXPECT_DOUBLE_EQ(s.angular_resolution_deg, 45.0);
  EXPECT_DOUBLE_EQ(s.angular_span_deg, 135.0);
  EXPECT_DOUBLE_EQ(s.angle_max_deg, 45.0);
  // 50 is the maximum and 4 of 12 readings: the no-return value.
  EXPECT_EQ(s.no_return_value_m, 50.0);
  EXPECT_EQ(s.no_returns, 4u);
  EXPECT_EQ(s.readings, 12u);
  EXPECT_DOUBLE_EQ(s.no_return_fraction, 4.0 / 12.0);
  EXPECT_EQ(s.min_reading_m, 0.5);
  EXPECT_EQ(s.max_reading_m, 50.0);
  EXPECT_EQ(s.max_valid_reading_m, 3.0);
  EXPECT_DOUBLE_EQ(s.odometry_path_m, 5.0);
  EXPECT_NEAR(s.odometry_rotation_rad, kPi / 2 + kPi, 1e-12);
  EXPECT_NEAR(s.odometry_rotation_deg, 270.0, 1e-9);
  EXPECT_EQ(s.time_backward_steps, 1u);
  EXPECT_DOUBLE_EQ(s.largest_backward_step_s, 0.25);
}

TEST(LogSummaryTest, VaryingBeamCountsAreFlaggedAndFormatted) {
  const std::string text = "FLASER 3 1 2 3 0 0 0 0 0 0 1 h 1\nFLASER 5 1 2 3 4 5 0 0 0 0 0 0 2 h 2\n";
  const LogSummary s = SummaryOfText(text);
  EXPECT_TRUE(s.readings_per_scan_varies);
  EXPECT_TRUE(s.geometry_varies);
  EXPECT_EQ(s.readings_per_scan_min, 3u);
  EXPECT_EQ(s.readings_per_scan_max, 5u);
  const std::string table = FormatLogSummary(s);
  EXPECT_THAT(table, HasSubstr("readings per scan        varies: 3 .. 5"));
  EXPECT_THAT(table, HasSubstr("laser scans              2"));
  // In a tiny log one reading is over 0.05 % of them: the maximum counts as a no-return cluster.
  EXPECT_THAT(table, HasSubstr("no-return value          5 m (rule: maximum reading cluster)"));
}

}  // namespace
}  // namespace slamtune::io
