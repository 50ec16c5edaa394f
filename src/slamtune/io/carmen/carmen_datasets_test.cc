// The shared Freiburg logs (/work/shared/datasets, MANIFEST.md) read through the CARMEN and
// relations readers. Skipped when the folder is absent. Each full log reads in well under a
// second (intel, 16 MB raw: about 0.3 s), so whole files are read.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/relations.h"

namespace slamtune::io {
namespace {

std::string DatasetPath(const std::string& file) { return std::string(SLAMTUNE_DATASETS_DIR) + "/" + file; }

struct Expected {
  const char* name;
  std::size_t scans;
  std::size_t readings_per_scan;
  double no_return_value;
  std::size_t relations;
};

class SharedLogTest : public ::testing::TestWithParam<Expected> {};

TEST_P(SharedLogTest, ScanCountsGeometryAndNoReturnValue) {
  const Expected& e = GetParam();
  const std::string path = DatasetPath(std::string(e.name) + ".clf.gz");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  const auto start = std::chrono::steady_clock::now();
  const LaserLog log = ReadCarmenLog(path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("read_seconds", std::to_string(seconds));
  EXPECT_LT(seconds, 2.0) << "reading " << e.name << " took " << seconds << " s";
  const LogSummary summary = SummarizeLog(log);
  EXPECT_EQ(summary.scans, e.scans);
  EXPECT_EQ(summary.readings_per_scan, e.readings_per_scan);
  EXPECT_FALSE(summary.readings_per_scan_varies);
  EXPECT_DOUBLE_EQ(log.no_return_value, e.no_return_value);
  EXPECT_EQ(log.no_return_rule, "maximum reading cluster");
  EXPECT_EQ(log.skipped_records, 0u);
  EXPECT_EQ(log.unknown_records, 0u);
  EXPECT_TRUE(log.compressed);
  EXPECT_EQ(ReadRelations(DatasetPath(std::string(e.name) + ".relations")).size(), e.relations);
}

INSTANTIATE_TEST_SUITE_P(Freiburg, SharedLogTest,
                         ::testing::Values(Expected{"aces", 7374, 180, 50.00, 1279},
                                           Expected{"intel", 13631, 180, 81.83, 2984},
                                           Expected{"mit-killian", 17480, 180, 51.22, 4677},
                                           Expected{"mit-csail", 1988, 361, 81.91, 1172}),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           for (char& c : name) c = (c == '-') ? '_' : c;
                           return name;
                         });

TEST(SharedLogTest, IntelTimeOrderAnomaliesAndRecordCounts) {
  const std::string path = DatasetPath("intel.clf.gz");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  const LaserLog log = ReadCarmenLog(path);
  EXPECT_EQ(log.time_backward_steps, 631u);
  EXPECT_NEAR(log.largest_backward_step_s, 0.897, 0.001);
  EXPECT_EQ(log.record_counts.at("ODOM"), 26915u);
  EXPECT_EQ(log.record_counts.at("PARAM"), 2u);
  EXPECT_EQ(log.record_counts.at("#"), 9u);
  EXPECT_EQ(log.total_no_returns, 68313u);  // MANIFEST: 68313 readings at 81.83
  EXPECT_EQ(log.lines_read, 40557u);
}

TEST(SharedLogTest, MaxScansReadsOnlyTheStart) {
  const std::string path = DatasetPath("intel.clf.gz");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  LogReadOptions options;
  options.max_scans = 100;
  const LaserLog log = ReadCarmenLog(path, options);
  EXPECT_EQ(log.scans.size(), 100u);
  EXPECT_TRUE(log.stopped_at_max_scans);
  EXPECT_LT(log.lines_read, 400u);
}

}  // namespace
}  // namespace slamtune::io
