#include "slamtune/tune/log_info.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/fixtures.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(SummarizeLogFile, ReadsTheLogWithTheInputOptions) {
  const std::filesystem::path dir = testing::UniqueTempDir("log_info");
  sim::SimulationOptions world;
  world.seed = 4;
  const sim::Simulation simulation = sim::Simulate(world);
  io::WriteCarmenLog((dir / "office.clf").string(), simulation.log);
  LogInfoOptions options;
  options.log = (dir / "office.clf").string();
  const io::LogSummary whole = SummarizeLogFile(options);
  EXPECT_EQ(whole.scans, simulation.log.scans.size());
  EXPECT_FALSE(whole.stopped_at_max_scans);
  options.input.max_scans = 40;
  const io::LogSummary slice = SummarizeLogFile(options);
  EXPECT_EQ(slice.scans, 40u);
  EXPECT_TRUE(slice.stopped_at_max_scans);

  const nlohmann::ordered_json j = ToJson(slice);
  EXPECT_EQ(j.at("scans"), 40);
  EXPECT_EQ(j.at("stopped_at_max_scans"), true);
  EXPECT_EQ(j.at("readings_per_scan"), slice.readings_per_scan);
  EXPECT_EQ(j.begin().key(), "path");
  EXPECT_EQ((--j.end()).key(), "input");
  std::filesystem::remove_all(dir);
}

TEST(SummarizeLogFile, ARecordingIsSummarisedWithItsTopic) {
  LogInfoOptions options;
  options.log = testing::FixturePath("recordings/office_zstd.mcap");
  const io::LogSummary summary = SummarizeLogFile(options);
  EXPECT_EQ(summary.scans, 655u);
  EXPECT_EQ(summary.readings_per_scan, 181);
  const nlohmann::ordered_json j = ToJson(summary);
  EXPECT_EQ(j.at("scans"), 655);
  EXPECT_THAT(j.at("input").dump(), HasSubstr("/scan"));
}

TEST(SummarizeLogFile, AnUnknownNoReturnValueIsNull) {
  io::LogSummary summary;
  summary.no_return_value_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(ToJson(summary).at("no_return_value").is_null());
  summary.no_return_value_m = 30.0;
  EXPECT_EQ(ToJson(summary).at("no_return_value"), 30.0);
}

TEST(SummarizeLogFile, MissingLogsAndBadOptionsAreRefused) {
  LogInfoOptions options;
  options.log = "/nonexistent/log.clf";
  EXPECT_THAT([&] { SummarizeLogFile(options); }, ThrowsMessage<InputError>(HasSubstr("/nonexistent/log.clf")));
  options.log = testing::FixturePath("recordings/office_zstd.mcap");
  options.input.beams = "sideways";
  EXPECT_THAT([&] { SummarizeLogFile(options); }, ThrowsMessage<InputError>(HasSubstr("sideways")));
}

}  // namespace
}  // namespace slamtune::tune
