// The mapper with two lasers (--beams per-geometry, docs/engine.md §3.5): a simulated corridor
// and an intel slice whose laser thins every other scan, run as two Karto lasers; each laser's
// own reading count, the lasers joined in one graph, determinism and shared work.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/mapper.h"
#include "slamtune/slam/testing/beam_counts.h"
#include "slamtune/slam/testing/corridor_log.h"
#include "slamtune/slam/testing/engine_state.h"

namespace slamtune::slam {
namespace {

// A corridor drive whose laser thins every other scan to 91 of its 181 beams (2 degree steps,
// exact angles): two beam geometries, run as two Karto lasers with --beams per-geometry (§3.5).
class MapperWithTwoLasers : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    io::LaserLog log = testing::ThinEveryNthScan(testing::SimulatedCorridorLog(), 2, 2);
    io::LaserLog node = log;
    io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
    io::HarmonizeBeams(io::BeamPolicy::kNode, &node);
    log_ = std::make_shared<const io::LaserLog>(std::move(log));
    node_log_ = std::make_shared<const io::LaserLog>(std::move(node));
    full_ = std::make_unique<LogRunner>(log_, testing::FastMapperParams());
    full_->RunToEnd();
  }
  static void TearDownTestSuite() {
    full_.reset();
    log_.reset();
    node_log_.reset();
  }

  static std::shared_ptr<const io::LaserLog> log_;
  static std::shared_ptr<const io::LaserLog> node_log_;
  static std::unique_ptr<LogRunner> full_;
};

std::shared_ptr<const io::LaserLog> MapperWithTwoLasers::log_;
std::shared_ptr<const io::LaserLog> MapperWithTwoLasers::node_log_;
std::unique_ptr<LogRunner> MapperWithTwoLasers::full_;

TEST_F(MapperWithTwoLasers, EveryScanReachesItsOwnLaser) {
  ASSERT_EQ(full_->lasers().geometries.size(), 2u);
  EXPECT_EQ(full_->lasers().geometries[0]->num_readings, 181);
  EXPECT_EQ(full_->lasers().geometries[1]->num_readings, 91);
  EXPECT_EQ(full_->lasers().names, (std::vector<std::string>{"laser_0", "laser_1"}));
  const RunSummary s = full_->Summary();
  EXPECT_EQ(s.scans_wrong_reading_count, 0);
  EXPECT_EQ(s.nodes + s.scans_not_moved, s.scans_offered);
  ASSERT_EQ(s.nodes_per_laser.size(), 2u);
  EXPECT_GT(s.nodes_per_laser[0], 10);
  EXPECT_GT(s.nodes_per_laser[1], 10);
  EXPECT_EQ(s.nodes_per_laser[0] + s.nodes_per_laser[1], s.nodes);
  // One sequential edge per scan after each laser's first.
  EXPECT_EQ(s.edges[static_cast<int>(EdgeKind::kSequential)], s.nodes - 2);
  EXPECT_EQ(s.edges[static_cast<int>(EdgeKind::kLaserLink)], 1);
  for (const LaserScan& scan : full_->mapper().scans()) {
    EXPECT_EQ(scan.laser, full_->lasers().LaserOf(static_cast<std::size_t>(scan.log_index)));
    EXPECT_EQ(&scan.geometry(), full_->lasers().geometries[scan.laser].get());
  }
  // The node drops every thinned scan.
  LogRunner node(node_log_, testing::FastMapperParams());
  node.RunToEnd();
  EXPECT_EQ(node.Summary().scans_wrong_reading_count, static_cast<int>(log_->scans.size() / 2));
  EXPECT_EQ(node.lasers().geometries.size(), 1u);
}

TEST_F(MapperWithTwoLasers, LasersAreJoinedInTheGraph) {
  const Mapper& m = full_->mapper();
  const ScansByLaser& by_laser = m.scans_by_laser();
  int across = 0;
  for (const Edge& e : m.graph().edges()) {
    const bool crosses = by_laser.laser_of(e.source) != by_laser.laser_of(e.target);
    if (e.kind == EdgeKind::kLaserLink) {
      // The second laser's first scan, linked from the first laser's first scan.
      EXPECT_EQ(e.source, by_laser.scans_of(0).front());
      EXPECT_EQ(e.target, by_laser.scans_of(1).front());
    } else if (e.kind == EdgeKind::kSequential || e.kind == EdgeKind::kRunningBuffer) {
      EXPECT_FALSE(crosses) << e.source << " -> " << e.target;
    }
    if (crosses) ++across;
  }
  EXPECT_GT(across, 10) << "near chains and loops should join the two lasers' scans";
  // Each laser's running buffer holds only its own scans.
  for (int laser = 0; laser < 2; ++laser) {
    for (int id : m.running_buffer(laser)) EXPECT_EQ(by_laser.laser_of(id), laser);
  }
}

TEST_F(MapperWithTwoLasers, RunsAreDeterministicAndCopiesContinueIdentically) {
  LogRunner again(log_, testing::FastMapperParams());
  again.RunToEnd();
  testing::ExpectSameEngineState(again, *full_);
  LogRunner half(log_, testing::FastMapperParams());
  while (half.next_index() < log_->scans.size() / 2) half.Step();
  LogRunner copy = half;
  copy.RunToEnd();
  half.RunToEnd();
  testing::ExpectSameEngineState(copy, *full_);
  testing::ExpectSameEngineState(half, *full_);
}

// The response bound (fast_matching/response_bound.h) also holds for chains of another laser.
TEST_F(MapperWithTwoLasers, SkippingUnlinkableNearChainsChangesNothing) {
  LogRunner all(log_, testing::FastMapperParams());
  all.set_skip_unlinkable_near_chains(false);
  all.RunToEnd();
  EXPECT_GT(full_->mapper().counters().near_chain_matches_skipped, 0);
  testing::ExpectSameEngineState(all, *full_, /*same_skips=*/false);
}

TEST_F(MapperWithTwoLasers, SharedWorkGivesTheSameResults) {
  SharedWork shared{std::make_shared<MatchCache>(), std::make_shared<SolveCache>(),
                    std::make_shared<BarycenterCache>()};
  LogRunner first(log_, testing::FastMapperParams(), shared);
  first.RunToEnd();
  LogRunner second(log_, testing::FastMapperParams(), shared);  // served by the caches
  second.RunToEnd();
  testing::ExpectSameEngineState(first, *full_);
  testing::ExpectSameEngineState(second, *full_);
  EXPECT_GT(shared.match_cache->counters().hits, 0u);
  EXPECT_EQ(shared.match_cache->counters().bypassed, 0u);  // matches across lasers are shared too
}

// The first 600 scans of intel with every other scan thinned to 90 of its 180 beams (2 degree
// steps, exact angles): the node drops half the scans, per-geometry maps them all, joins the
// two lasers and is deterministic.
TEST(Mapper, TwoLasersOnAnIntelSlice) {
  const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/intel.clf.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  io::LaserLog whole = io::ReadCarmenLog(path);
  whole.scans.resize(std::min<std::size_t>(whole.scans.size(), 600));
  io::LaserLog log = testing::ThinEveryNthScan(std::move(whole), 2, 2);
  io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
  const auto shared_log = std::make_shared<const io::LaserLog>(std::move(log));
  LogRunner a(shared_log, MapperParams{});
  while (a.next_index() < 300) a.Step();
  LogRunner b = a;
  a.RunToEnd();
  b.RunToEnd();
  testing::ExpectSameEngineState(a, b);
  const RunSummary s = a.Summary();
  EXPECT_EQ(s.scans_wrong_reading_count, 0);
  ASSERT_EQ(s.nodes_per_laser.size(), 2u);
  EXPECT_GT(s.nodes_per_laser[0], 20);
  EXPECT_GT(s.nodes_per_laser[1], 20);
  EXPECT_EQ(s.edges[static_cast<int>(EdgeKind::kLaserLink)], 1);
  const ScansByLaser& by_laser = a.mapper().scans_by_laser();
  int across = 0;
  for (const Edge& e : a.mapper().graph().edges()) across += by_laser.laser_of(e.source) != by_laser.laser_of(e.target);
  EXPECT_GT(across, 20);
}

TEST(Mapper, EachLaserChecksItsOwnReadingCount) {
  MapperParams p;
  p.use_scan_matching = false;
  Mapper mapper(p);
  auto three = std::make_shared<LaserGeometry>();
  three->angular_resolution = 0.1;
  three->num_readings = 3;
  auto two = std::make_shared<LaserGeometry>(*three);
  two->num_readings = 2;
  const auto ranges3 = std::make_shared<const std::vector<double>>(std::vector<double>{1, 1, 1});
  const auto ranges2 = std::make_shared<const std::vector<double>>(std::vector<double>{1, 1});
  const auto scan = [](const auto& geometry, const auto& ranges, double x, int laser) {
    LaserScan s(geometry, ranges, {x, 0, 0}, 0.0);
    s.laser = laser;
    return s;
  };
  EXPECT_EQ(mapper.Process(scan(three, ranges3, 0.0, 0)).outcome, ProcessResult::Outcome::kProcessed);
  // Laser 1's first scan: its own count, and its own first scan (no movement test).
  EXPECT_EQ(mapper.Process(scan(two, ranges2, 0.0, 1)).outcome, ProcessResult::Outcome::kProcessed);
  EXPECT_EQ(mapper.Process(scan(two, ranges2, 1.0, 0)).outcome, ProcessResult::Outcome::kWrongReadingCount);
  EXPECT_EQ(mapper.Process(scan(three, ranges3, 1.0, 1)).outcome, ProcessResult::Outcome::kWrongReadingCount);
  EXPECT_EQ(mapper.Process(scan(two, ranges2, 0.05, 1)).outcome, ProcessResult::Outcome::kNotMoved);
  EXPECT_EQ(mapper.Process(scan(three, ranges3, 1.0, 0)).outcome, ProcessResult::Outcome::kProcessed);
  EXPECT_EQ(mapper.scans_by_laser().scans_of(0).size(), 2u);
  EXPECT_EQ(mapper.scans_by_laser().scans_of(1).size(), 1u);
  EXPECT_EQ(mapper.last_processed(), 2);
}

}  // namespace
}  // namespace slamtune::slam
