#include "slamtune/io/log_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/ros/ros_recording.h"

namespace slamtune::io {
namespace {

namespace fs = std::filesystem;

class LogReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("slamtune_log_reader_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  fs::path dir_;
};

// A CARMEN log whose FLASER scans alternate between 180 and 181 readings, as a real one does.
std::string AlternatingLog(int scans) {
  std::ostringstream out;
  for (int k = 0; k < scans; ++k) {
    const int n = k % 2 == 0 ? 181 : 180;
    out << "FLASER " << n;
    for (int i = 0; i < n; ++i) out << ' ' << 2.0 + 0.01 * i;
    out << " " << 0.1 * k << " 0 0 " << 0.1 * k << " 0 0 " << 10.0 + k << " nohost " << k << "\n";
  }
  return out.str();
}

TEST_F(LogReaderTest, CarmenScansOfVaryingCountsAreKeptAsRecordedAndTheNodesDropsCounted) {
  const std::string path = Write("alternating.clf", AlternatingLog(7));
  const LaserLog log = ReadLaserLog(path);
  ASSERT_EQ(log.scans.size(), 7u);
  EXPECT_EQ(log.scans[1].ranges.size(), 180u);
  EXPECT_EQ(log.beams.scans_resampled, 0u);
  EXPECT_EQ(log.beams.slam_karto.dropped, 3u);
  EXPECT_THAT(DescribeLogInput(log),
              ::testing::Contains("beams: the node (slam_karto and slam_toolbox alike) drops 3 of 7 scans: their beam "
                                  "count differs from the first scan's (181); make the driver publish a fixed count"));

  LogReadOptions nearest;
  nearest.beams = BeamPolicy::kNearestBeam;
  const LaserLog resampled = ReadLaserLog(path, nearest);
  for (const LaserScanRecord& s : resampled.scans) EXPECT_EQ(s.ranges.size(), 181u);
  EXPECT_EQ(resampled.beams.scans_resampled, 3u);
  EXPECT_EQ(resampled.beams.readings_outside, 3u);  // the +90 deg beam of each 180-reading scan
  // 180 readings cover -90 .. +89 at 1 deg: the same angles as the first 180 of 181.
  EXPECT_DOUBLE_EQ(resampled.scans[1].ranges[179], 2.0 + 0.01 * 179);
  EXPECT_TRUE(std::isinf(resampled.scans[1].ranges[180]));
  EXPECT_THAT(
      DescribeLogInput(resampled),
      ::testing::Contains(::testing::HasSubstr("beams: --beams nearest-beam: 3 scans resampled onto 181 beams")));
}

TEST_F(LogReaderTest, RecordingsAreToldByContentNotName) {
  const std::string text = Write("looks_like.mcap", AlternatingLog(2));
  EXPECT_EQ(DetectRecordingKind(text), RecordingKind::kCarmenLog);
  EXPECT_EQ(ReadLaserLog(text).scans.size(), 2u);
  const std::string garbage = Write("garbage.bag", std::string("\x89MCAP0\r\n", 8) + std::string(40, '\xff'));
  EXPECT_THROW(ReadLaserLog(garbage), InputError);
  EXPECT_THROW(ReadLaserLog((dir_ / "missing.mcap").string()), InputError);
}

}  // namespace
}  // namespace slamtune::io
