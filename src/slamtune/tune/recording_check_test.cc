#include "slamtune/tune/recording_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/fixtures.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(CheckRecordingFile, ACleanRecordingHasNoProblem) {
  RecordingCheckOptions options;
  options.log = testing::FixturePath("recordings/office_zstd.mcap");
  const io::CheckReport report = CheckRecordingFile(options);
  EXPECT_TRUE(report.ok());
  const nlohmann::ordered_json j = ToJson(report);
  EXPECT_EQ(j.at("ok"), true);
  EXPECT_TRUE(j.at("problems").empty());
  EXPECT_EQ(j.at("path"), report.path);
  EXPECT_FALSE(j.at("facts").empty());
  EXPECT_TRUE(j.contains("scans_not_used"));
}

TEST(CheckRecordingFile, APlantedGapInTfIsAProblemByKind) {
  RecordingCheckOptions options;
  options.log = testing::FixturePath("recordings/fault_tf_gap.mcap");
  const io::CheckReport report = CheckRecordingFile(options);
  ASSERT_FALSE(report.ok());
  EXPECT_TRUE(report.Has(io::ProblemKind::kTfMissing));
  const nlohmann::ordered_json j = ToJson(report);
  EXPECT_EQ(j.at("ok"), false);
  ASSERT_EQ(j.at("problems").size(), report.problems.size());
  EXPECT_EQ(j.at("problems")[0].at("kind"), io::ProblemKindName(report.problems[0].kind));
  EXPECT_EQ(j.at("problems")[0].at("count"), report.problems[0].count);
}

TEST(CheckRecordingFile, TheLimitsDecideWhatIsAProblem) {
  RecordingCheckOptions options;
  options.log = testing::FixturePath("recordings/office_zstd.mcap");
  options.check.max_speed_mps = 0.01;  // the drive is faster than this everywhere
  EXPECT_FALSE(CheckRecordingFile(options).ok());
}

TEST(CheckRecordingFile, MissingFilesAndBadOptionsAreRefused) {
  RecordingCheckOptions options;
  options.log = "/nonexistent/drive.mcap";
  EXPECT_THAT([&] { CheckRecordingFile(options); }, ThrowsMessage<InputError>(HasSubstr("/nonexistent/drive.mcap")));
  options.log = testing::FixturePath("recordings/office_zstd.mcap");
  options.input.scan_topic = "/no_such_scan";
  EXPECT_THAT([&] { CheckRecordingFile(options); }, ThrowsMessage<InputError>(HasSubstr("/no_such_scan")));
}

}  // namespace
}  // namespace slamtune::tune
