#include "slamtune/io/trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <source_location>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/testing/read_error.h"

namespace slamtune::io {
namespace {

using slamtune::testing::WriteTempFile;

TEST(TrajectoryTest, ReadsPosesAndSkipsComments) {
  const auto poses = ReadTrajectory(
      WriteTempFile("trajectory_test", "ok", "# t x y theta\n  \n10.5 1 2 0.5\n\t# indented comment\n11 -1 -2 -0.5\n"));
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].time, 10.5);
  EXPECT_EQ(poses[0].pose, (Pose2{1, 2, 0.5}));
  EXPECT_EQ(poses[1].pose, (Pose2{-1, -2, -0.5}));
}

TEST(TrajectoryTest, RoundTripKeepsMicrosecondsAndNineDigits) {
  const std::vector<TimedPose> poses = {{976052857.337284, {12.3456789, -0.000123456789, 3.14159265}},
                                        {1134864629.895182, {-45.6789012, 7.0, -1.23456789}}};
  const std::string path = slamtune::testing::TempFilePath("trajectory_test", "roundtrip");
  WriteTrajectory(path, poses);
  const auto back = ReadTrajectory(path);
  ASSERT_EQ(back.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(back[i].time, poses[i].time, 5e-7);
    EXPECT_NEAR(back[i].pose.x, poses[i].pose.x, 1e-8 * std::abs(poses[i].pose.x));
    EXPECT_NEAR(back[i].pose.y, poses[i].pose.y, 1e-8 * std::abs(poses[i].pose.y));
    EXPECT_NEAR(back[i].pose.theta, poses[i].pose.theta, 1e-8);
  }
}

// The error for a file holding `text`, after the file's path.
std::string ErrorFor(const std::string& name, const std::string& text,
                     std::source_location where = std::source_location::current()) {
  return testing::ErrorAfterPath(ReadTrajectory, "trajectory_test", name, text, where);
}

TEST(TrajectoryTest, ErrorsNameFileLineAndProblem) {
  EXPECT_EQ(ErrorFor("cols", "1 0 0 0\n2 0 0\n"), ":2: expected 4 columns (timestamp x y theta), found 3");
  EXPECT_EQ(ErrorFor("text", "1 0 zero 0\n"), ":1: column 3 (y) is not a number: 'zero'");
  EXPECT_EQ(ErrorFor("nan", "1 0 0 0\n2 0 0 -nan\n"), ":2: column 4 (theta) is not finite: -nan");
  EXPECT_EQ(ErrorFor("inf", "-inf 0 0 0\n"), ":1: column 1 (timestamp) is not finite: -inf");
  EXPECT_THAT([] { ReadTrajectory("/nonexistent/t.txt"); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("/nonexistent/t.txt: cannot open")));
}

TEST(TrajectoryTest, TwoDifferentPosesWithOneTimestampNameTheSecondLine) {
  EXPECT_EQ(ErrorFor("two", "# t x y theta\n10.5 1 2 0.5\n11 0 0 0\n10.5 1 2.5 0.5\n"),
            ":4: second pose for timestamp 10.5 (line 2 has 1 2 0.5, this line 1 2.5 0.5): a "
            "trajectory needs one pose per timestamp");
  EXPECT_EQ(ErrorFor("spelled", "7.000000 0 0 0\n7 0 0 0.25\n"),  // same time, other text
            ":2: second pose for timestamp 7 (line 1 has 0 0 0, this line 0 0 0.25): a "
            "trajectory needs one pose per timestamp");
}

TEST(TrajectoryTest, AnExactlyRepeatedPoseIsReadOnce) {
  const auto poses = ReadTrajectory(WriteTempFile("trajectory_test", "repeat", "1 0 0 0\n2 1 0 0\n2 1 0 0\n3 2 0 0\n"));
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses[2].time, 3.0);
}

TEST(TrajectoryTest, ByteOrderMarkDoesNotHideTheFirstPose) {
  const auto poses = ReadTrajectory(WriteTempFile("trajectory_test", "bom",
                                                  "\xEF\xBB\xBF"
                                                  "1 0.5 0 0\n2 1 0 0\n"));
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].pose.x, 0.5);
}

TEST(TrajectoryTest, EmptyFileIsEmptyTrajectory) {
  EXPECT_TRUE(ReadTrajectory(WriteTempFile("trajectory_test", "empty", "# only\n")).empty());
}

TEST(TrajectoryTest, UnwritablePathThrows) {
  EXPECT_THROW(WriteTrajectory("/nonexistent/dir/t.txt", {{0, {}}}), InputError);
}

}  // namespace
}  // namespace slamtune::io
