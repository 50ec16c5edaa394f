#include "slamtune/slam/log_runner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <utility>

#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/carmen/carmen_reader.h"

namespace slamtune::slam {
namespace {

io::LaserScanRecord Record(const Pose2& pose, double time, double max_range = 50.0) {
  io::LaserScanRecord r;
  r.angle_min = -kPi / 2;
  r.angle_increment = kPi / 4;
  r.ranges = {2.0, 2.5, 3.0, 2.5, 2.0};
  r.max_range = max_range;
  r.laser_pose = r.robot_pose = pose;
  r.ipc_time = time;
  return r;
}

// The run of `log` with scan matching off: its nodes, skips and trajectory follow from odometry
// alone.
RunResult RunWithoutMatching(std::shared_ptr<const io::LaserLog> log, MapperParams params) {
  params.use_scan_matching = false;
  return RunLog(std::move(log), params);
}

TEST(GeometryForRecord, CapsMaxRangeAndAppliesTheThresholdRule) {
  MapperParams p;
  io::LaserScanRecord r = Record({}, 0.0, 81.83);
  LaserGeometry g = GeometryForRecord(r, p);
  EXPECT_EQ(g.max_range, 80.0);  // intel: min(80, 81.83)
  EXPECT_EQ(g.range_threshold, 12.0);
  EXPECT_EQ(g.num_readings, 5);
  EXPECT_EQ(g.offset, Pose2{});
  r.max_range = 51.22;
  EXPECT_EQ(GeometryForRecord(r, p).max_range, 51.22);  // mit-killian
  r.max_range = std::numeric_limits<double>::infinity();
  EXPECT_EQ(GeometryForRecord(r, p).max_range, 80.0);  // no no-return value: the cap
  r.max_range = 8.0;
  EXPECT_EQ(GeometryForRecord(r, p).range_threshold, 8.0);
  p = MapperParams::Preset("slam_toolbox");
  r.max_range = 50.0;
  EXPECT_EQ(GeometryForRecord(r, p).range_threshold, 20.0);
}

// `record` with `n` readings of 2 m, `increment` apart from `angle_min`.
io::LaserScanRecord WithBeams(io::LaserScanRecord record, std::size_t n, double angle_min, double increment) {
  record.ranges.assign(n, 2.0);
  record.angle_min = angle_min;
  record.angle_increment = increment;
  return record;
}

TEST(LasersOf, OneLaserFromTheFirstScanUnlessPerGeometry) {
  io::LaserLog log;
  log.scans = {WithBeams(Record({}, 0), 5, -1.0, 0.5), WithBeams(Record({}, 1), 3, -1.0, 1.0),
               WithBeams(Record({}, 2), 5, -1.0 + 5e-7, 0.5),  // the first geometry within 1e-6 rad
               WithBeams(Record({}, 3), 5, -0.9, 0.5), WithBeams(Record({}, 4), 3, -1.0, 1.0)};
  const MapperParams p;
  io::HarmonizeBeams(io::BeamPolicy::kNode, &log);
  LogLasers one = LasersOf(log, p, OdometryFrameOf(log));
  ASSERT_EQ(one.geometries.size(), 1u);
  EXPECT_EQ(one.geometries[0]->num_readings, 5);
  EXPECT_TRUE(one.laser_of_scan.empty());
  EXPECT_EQ(one.LaserOf(4), 0);
  EXPECT_EQ(one.names, std::vector<std::string>{"laser_0"});
  io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
  const LogLasers lasers = LasersOf(log, p, OdometryFrameOf(log));
  ASSERT_EQ(lasers.geometries.size(), 3u);  // in order of first appearance
  EXPECT_EQ(lasers.laser_of_scan, (std::vector<int>{0, 1, 0, 2, 1}));
  EXPECT_EQ(lasers.geometries[1]->num_readings, 3);
  EXPECT_EQ(lasers.geometries[1]->angular_resolution, 1.0);
  EXPECT_EQ(lasers.geometries[2]->min_angle, -0.9);
  EXPECT_EQ(lasers.geometries[0]->min_angle, -1.0);  // the first scan that has it
  EXPECT_EQ(GeometryKeyWords(*lasers.geometries[0]), GeometryKeyWords(GeometryForRecord(log.scans[0], p)));
  EXPECT_EQ(lasers.names, (std::vector<std::string>{"laser_0", "laser_1", "laser_2"}));
}

TEST(LasersOf, NamesSortInLaserOrder) {
  io::LaserLog log;
  for (int k = 0; k < 12; ++k) log.scans.push_back(WithBeams(Record({}, k), 3 + k, -1.0, 0.1));
  io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
  const LogLasers lasers = LasersOf(log, MapperParams{}, OdometryFrameOf(log));
  ASSERT_EQ(lasers.names.size(), 12u);
  EXPECT_EQ(lasers.names.front(), "laser_00");
  EXPECT_EQ(lasers.names.back(), "laser_11");
  EXPECT_TRUE(std::is_sorted(lasers.names.begin(), lasers.names.end()));
}

// Odometry only: the node drops the scans of the second count, per-geometry maps them with a
// laser of their own, whose moved-enough test looks at its own scans only (§3.5).
TEST(LogRunner, PerGeometryKeepsScansOfAnotherCount) {
  io::LaserLog log;
  for (int k = 0; k < 5; ++k) {
    log.scans.push_back(WithBeams(Record({0.5 * k, 0, 0}, k), k % 2 == 0 ? 5 : 3, -1.0, k % 2 == 0 ? 0.5 : 1.0));
  }
  MapperParams p;
  p.use_scan_matching = false;
  p.minimum_travel_distance = 0.8;
  io::HarmonizeBeams(io::BeamPolicy::kNode, &log);
  LogRunner node(std::make_shared<const io::LaserLog>(log), p);
  node.RunToEnd();
  EXPECT_EQ(node.Summary().scans_wrong_reading_count, 2);
  EXPECT_EQ(node.Summary().nodes, 3);
  EXPECT_EQ(node.Summary().nodes_per_laser, std::vector<int>{3});
  io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
  LogRunner per_geometry(std::make_shared<const io::LaserLog>(log), p);
  per_geometry.RunToEnd();
  const RunSummary s = per_geometry.Summary();
  EXPECT_EQ(s.scans_wrong_reading_count, 0);
  EXPECT_EQ(s.scans_not_moved, 0);  // each laser moved 1 m since its own last scan
  EXPECT_EQ(s.nodes_per_laser, (std::vector<int>{3, 2}));
  const std::vector<LaserScan>& scans = per_geometry.mapper().scans();
  ASSERT_EQ(scans.size(), 5u);
  EXPECT_EQ(scans[1].laser, 1);
  EXPECT_EQ(scans[1].geometry().num_readings, 3);
  EXPECT_EQ(scans[1].geometry().angular_resolution, 1.0);
}

TEST(LogRunner, TrajectoryComposesOdometryOfSkippedScans) {
  auto log = std::make_shared<io::LaserLog>();
  log->path = "<memory>";
  // Scan 1 moves 5 cm (not enough), scan 2 moves 30 cm from scan 0 (processed), scan 3 turns a little.
  log->scans = {Record({0, 0, 0}, 1.0), Record({0.05, 0, 0}, 2.0), Record({0.3, 0, 0}, 3.0),
                Record({0.32, 0.01, 0.05}, 4.0)};
  const RunResult run = RunWithoutMatching(log, MapperParams{});
  const RunSummary& s = run.summary;
  EXPECT_EQ(s.nodes, 2);
  EXPECT_EQ(s.scans_not_moved, 2);
  EXPECT_EQ(s.log_duration_s, 3.0);
  const auto& t = run.trajectory;
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[1].time, 2.0);
  EXPECT_NEAR(t[1].pose.x, 0.05, 1e-12);
  EXPECT_NEAR(t[3].pose.y, 0.01, 1e-12);
  EXPECT_NEAR(t[3].pose.theta, 0.05, 1e-12);
}

TEST(LogRunner, ThrottleKeepsEveryNthScanAsSlamKarto) {
  auto log = std::make_shared<io::LaserLog>();
  for (int i = 0; i < 9; ++i) log->scans.push_back(Record({0.5 * i, 0, 0}, i));
  MapperParams p;
  p.throttle_scans = 3;
  const RunResult run = RunWithoutMatching(log, p);
  EXPECT_EQ(run.summary.scans_offered, 3);
  EXPECT_EQ(run.summary.scans_refused_by_node[static_cast<int>(NodeVerdict::kThrottled)], 6);
  EXPECT_EQ(run.summary.nodes, 3);
  EXPECT_EQ(run.summary.loop_closures.size(), 0u);
  // slam_karto keeps the 3rd, 6th and 9th message.
  const std::vector<io::TimedPose>& t = run.trajectory;
  EXPECT_NEAR(t[4].pose.x, 2.0, 1e-12);
}

TEST(LogRunner, SynchronousNodeKeepsRotationsFromKarto) {
  // Five scans driving 1 m each, then ten turning in place: the synchronous node hands Karto
  // the first and the fifth only (the counter, then no travel), the asynchronous node every one.
  auto log = std::make_shared<io::LaserLog>();
  for (int i = 0; i < 5; ++i) log->scans.push_back(Record({1.0 * i, 0, 0}, i));
  for (int i = 5; i < 15; ++i) log->scans.push_back(Record({4.0, 0, 0.3 * (i - 4)}, i));
  const RunSummary s = RunWithoutMatching(log, MapperParams::Preset("slam_toolbox_sync")).summary;
  EXPECT_EQ(s.scans_offered, 2);
  EXPECT_EQ(s.nodes, 2);
  EXPECT_EQ(s.scans_refused_by_node[static_cast<int>(NodeVerdict::kWarmingUp)], 3);
  EXPECT_EQ(s.scans_refused_by_node[static_cast<int>(NodeVerdict::kNotMoved)], 10);
  EXPECT_EQ(s.scans_refused_by_node_total(), 13);
  const RunSummary every = RunWithoutMatching(log, MapperParams::Preset("slam_toolbox")).summary;
  EXPECT_EQ(every.scans_offered, 15);
  EXPECT_EQ(every.scans_refused_by_node_total(), 0);
  EXPECT_GT(every.nodes, s.nodes);  // Karto's own heading test accepts the turns
}

// Every scan the run did not map, by why: the node's filter by verdict, Karto's travel gate, the
// reading count as the engine refused it, beside what the recording lost.
TEST(RunLosses, CountEveryScanNotMappedByWhy) {
  auto log = std::make_shared<io::LaserLog>();
  for (int i = 0; i < 5; ++i) log->scans.push_back(Record({1.0 * i, 0, 0}, i));
  for (int i = 5; i < 15; ++i) log->scans.push_back(Record({4.0, 0, 0.3 * (i - 4)}, i));
  log->scans[7].ranges.push_back(1.0);  // six readings: the laser expects five
  log->recording.emplace();
  log->recording->scans_unplaced = 2;
  MapperParams async = MapperParams::Preset("slam_toolbox");
  async.minimum_travel_heading = 10.0;  // Karto keeps no turn on the spot
  const io::ScanLosses losses = RunLosses(*log, RunWithoutMatching(log, async).summary, async.node_mode);
  EXPECT_EQ(losses.Find(io::ScanLossKind::kNoOdometry)->count, 2u);
  EXPECT_EQ(losses.Find(io::ScanLossKind::kWrongReadingCount)->count, 1u);
  EXPECT_EQ(losses.Find(io::ScanLossKind::kFilteredByNode)->count, 0u);
  EXPECT_EQ(losses.Find(io::ScanLossKind::kNotMoved)->count, 9u);
  EXPECT_EQ(losses.kinds.size(), static_cast<std::size_t>(io::kNumScanLossKinds));
  const MapperParams sync = MapperParams::Preset("slam_toolbox_sync");
  const io::ScanLosses node = RunLosses(*log, RunWithoutMatching(log, sync).summary, sync.node_mode);
  const io::ScanLoss& by_node = *node.Find(io::ScanLossKind::kFilteredByNode);
  EXPECT_EQ(by_node.count, 13u);
  EXPECT_EQ(by_node.by.at("warming_up"), 3u);
  EXPECT_EQ(by_node.by.at("not_moved"), 10u);
  EXPECT_EQ(by_node.by.at("throttled"), 0u);
  EXPECT_THAT(by_node.why, ::testing::HasSubstr("node mode slam_toolbox_sync"));
}

TEST(LogRunner, EmptyLogIsAnInputError) {
  auto log = std::make_shared<io::LaserLog>();
  log->path = "empty.clf";
  EXPECT_THROW(LogRunner(log, MapperParams{}), InputError);
}

// Node counts depend only on odometry and HasMovedEnough (§3.2 step 5), so they can be checked
// on a whole (short) dataset without scan matching: the reference Karto build made 1469 nodes
// on mit-csail.
TEST(LogRunner, MitCsailNodeCountMatchesReferenceKarto) {
  const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/mit-csail.clf.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  auto log = std::make_shared<const io::LaserLog>(io::ReadCarmenLog(path));
  const RunSummary s = RunWithoutMatching(log, MapperParams{}).summary;
  EXPECT_EQ(s.scans_read, 1988);
  EXPECT_EQ(s.nodes, 1469);
  EXPECT_EQ(s.laser_max_range, 80.0);
}

// The back end's arithmetic decides loops on mit-killian (backend/spa_system.h): with r = 5.90, g = 8,
// p = 0.7, the reference Karto build (open_karto + slam_karto's SPA) closes its first four loops
// at these log scans with these coarse responses; the fourth (6314) needs bit-exact solves after
// the first three: with algebraically equal variants of the edge measurement, mean heading and
// SPA arithmetic the engine closes one at 6267 instead.
TEST(LogRunner, MitKillianFirstLoopsMatchReferenceKarto) {
  const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/mit-killian.clf.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  io::LaserLog log = io::ReadCarmenLog(path);
  ASSERT_GT(log.scans.size(), 6400u);
  log.scans.resize(6400);
  MapperParams p = MapperParams::Preset("slam_karto");
  p.loop_search_maximum_distance = 5.90;
  p.loop_match_minimum_chain_size = 8;
  p.loop_match_minimum_response_coarse = 0.7;
  LogRunner runner(std::make_shared<const io::LaserLog>(std::move(log)), p);
  runner.RunToEnd();
  const std::vector<LoopClosureRecord> loops = runner.Summary().loop_closures;
  const std::vector<std::pair<int, double>> expected{
      {1132, 0.8465}, {2642, 0.7565}, {4149, 0.748889}, {6314, 0.722444}};
  ASSERT_EQ(loops.size(), expected.size());
  for (std::size_t k = 0; k < loops.size(); ++k) {
    EXPECT_EQ(loops[k].log_index, expected[k].first) << k;
    EXPECT_NEAR(loops[k].coarse_response, expected[k].second, 5e-7) << k;
  }
}

}  // namespace
}  // namespace slamtune::slam
