// The same simulated drive (office world, laser mounted off the base) read from its CARMEN log
// and from bags written by independent libraries (tests/fixtures/recordings, README there):
// the same scans, the same poses, and the same SLAM run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "slamtune/common/testing/fixtures.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::FixturePath;

// The world the fixtures were made from (the simulate command in the fixtures' README).
const io::LaserLog& WorldLog() {
  static const io::LaserLog log = [] {
    sim::SimulationOptions o;
    o.world = "office";
    o.seed = 1;
    o.speed_mps = 1.0;
    o.scan_rate_hz = 3.0;
    o.laser_offset = Pose2{0.12, -0.04, 0.05};
    o.laser.float32_values = true;
    o.laser.range_resolution_m = 0.001953125;
    return sim::Simulate(o).log;
  }();
  return log;
}

void ExpectSameScans(const io::LaserLog& bag, const io::LaserLog& carmen, std::size_t count) {
  ASSERT_EQ(bag.scans.size(), count);
  for (std::size_t k = 0; k < count; ++k) {
    const io::LaserScanRecord &b = bag.scans[k], &c = carmen.scans[k];
    ASSERT_EQ(b.ranges, c.ranges) << "scan " << k;
    ASSERT_EQ(b.angle_min, c.angle_min) << "scan " << k;
    ASSERT_EQ(b.angle_increment, c.angle_increment) << "scan " << k;
    ASSERT_EQ(b.max_range, c.max_range) << "scan " << k;
    ASSERT_EQ(b.ipc_time, c.ipc_time) << "scan " << k;
    for (const auto& [got, want] : {std::pair{b.robot_pose, c.robot_pose}, std::pair{b.laser_pose, c.laser_pose},
                                    std::pair{b.laser_offset, c.laser_offset}}) {
      ASSERT_NEAR(got.x, want.x, 1e-9) << "scan " << k;
      ASSERT_NEAR(got.y, want.y, 1e-9) << "scan " << k;
      ASSERT_NEAR(got.theta, want.theta, 1e-9) << "scan " << k;
    }
  }
}

class RecordingRuns : public ::testing::TestWithParam<std::string> {};

TEST_P(RecordingRuns, BagGivesTheCarmenLogsScansAndPoses) {
  const io::LaserLog bag = io::ReadLaserLog(FixturePath("recordings/" + GetParam()));
  ExpectSameScans(bag, WorldLog(), WorldLog().scans.size());
  ASSERT_TRUE(bag.recording.has_value());
  EXPECT_EQ(bag.recording->scan_topic, "/scan");
  EXPECT_EQ(bag.recording->base_frame, "base_footprint");
  EXPECT_EQ(bag.recording->scans_unplaced, 0u);
}

// The run makes the same decisions — nodes, edges, loop closures and their responses — and its
// trajectory agrees to 1e-7 m (the inputs differ in the last bits: headings pass through
// quaternions, the CARMEN laser poses and the offset derived from them through 12-decimal
// text; measured 1.1e-8 m at most).
TEST_P(RecordingRuns, SlamRunIsTheSameAsOnTheCarmenLog) {
  static const RunResult reference =
      RunLog(std::make_shared<const io::LaserLog>(WorldLog()), MapperParams::Preset("slam_karto"));
  const RunResult run =
      RunLog(std::make_shared<const io::LaserLog>(io::ReadLaserLog(FixturePath("recordings/" + GetParam()))),
             MapperParams::Preset("slam_karto"));
  EXPECT_EQ(run.summary.nodes, reference.summary.nodes);
  EXPECT_EQ(run.summary.edges, reference.summary.edges);
  ASSERT_EQ(run.summary.loop_closures.size(), reference.summary.loop_closures.size());
  EXPECT_GE(reference.summary.loop_closures.size(), 1u);
  for (std::size_t k = 0; k < run.summary.loop_closures.size(); ++k) {
    EXPECT_EQ(run.summary.loop_closures[k].log_index, reference.summary.loop_closures[k].log_index);
    EXPECT_NEAR(run.summary.loop_closures[k].coarse_response, reference.summary.loop_closures[k].coarse_response,
                1e-12);
  }
  ASSERT_EQ(run.trajectory.size(), reference.trajectory.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < run.trajectory.size(); ++k) {
    largest = std::max({largest, std::fabs(run.trajectory[k].pose.x - reference.trajectory[k].pose.x),
                        std::fabs(run.trajectory[k].pose.y - reference.trajectory[k].pose.y)});
  }
  RecordProperty("largest_position_difference_m", std::to_string(largest));
  for (std::size_t k = 0; k < run.trajectory.size(); ++k) {
    ASSERT_NEAR(run.trajectory[k].pose.x, reference.trajectory[k].pose.x, 1e-7) << k;
    ASSERT_NEAR(run.trajectory[k].pose.y, reference.trajectory[k].pose.y, 1e-7) << k;
    ASSERT_NEAR(run.trajectory[k].pose.theta, reference.trajectory[k].pose.theta, 1e-7) << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, RecordingRuns,
                         ::testing::Values("office_zstd.mcap", "office_db3", "office_lz4.bag", "office_bz2.bag"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

// The slices hold the first 120 scans, in the other container variants.
TEST(RecordingSlices, EveryVariantGivesTheFirstScansOfTheDrive) {
  for (const char* name : {"office_slice_none.mcap", "office_slice_lz4.mcap", "office_slice_nochunk.mcap",
                           "office_slice_unindexed.mcap", "office_slice_none.bag"}) {
    SCOPED_TRACE(name);
    const io::LaserLog bag = io::ReadLaserLog(FixturePath(std::string("recordings/") + name));
    ExpectSameScans(bag, WorldLog(), 120);
  }
  const io::LaserLog cut = io::ReadLaserLog(FixturePath("recordings/office_slice_unindexed.mcap"));
  EXPECT_FALSE(cut.recording->data_end.complete);
}

}  // namespace
}  // namespace slamtune::slam
