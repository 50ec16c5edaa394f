// End-to-end tests of the mapper on a simulated corridor loop (sim/), driven through the
// LogRunner step API: determinism, forking the engine state, changing loop-closure parameters
// on a copy, the coarse gate's strictness and the "loop closed without an edge" quirk. Two
// lasers: mapper_two_lasers_test.cc.
#include "slamtune/slam/mapper.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/testing/beam_counts.h"
#include "slamtune/slam/testing/corridor_log.h"
#include "slamtune/slam/testing/engine_state.h"

namespace slamtune::slam {
namespace {

class MapperOnCorridor : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    log_ = std::make_shared<const io::LaserLog>(testing::SimulatedCorridorLog());
    full_ = std::make_unique<LogRunner>(log_, testing::FastMapperParams());
    full_->RunToEnd();
    // The first accepted loop and a snapshot of the engine just before its scan.
    for (const LoopAttempt& a : full_->mapper().loop_attempts()) {
      if (a.accepted) {
        loop_ = a;
        break;
      }
    }
    if (loop_.log_index < 0) return;
    before_loop_ = std::make_unique<LogRunner>(log_, testing::FastMapperParams());
    while (before_loop_->next_index() < static_cast<std::size_t>(loop_.log_index)) before_loop_->Step();
  }
  static void TearDownTestSuite() {
    full_.reset();
    before_loop_.reset();
    log_.reset();
  }
  void SetUp() override { ASSERT_GE(loop_.log_index, 0) << "the corridor run closed no loop; the fixture needs one"; }

  // Index (in the attempts of `runner`) of the attempt made for `log_index` on `chain_first`.
  static const LoopAttempt* AttemptFor(const LogRunner& runner, int log_index, int chain_first) {
    for (const LoopAttempt& a : runner.mapper().loop_attempts()) {
      if (a.log_index == log_index && a.chain_first == chain_first) return &a;
    }
    return nullptr;
  }

  // The attempt on the fixture's loop when its scan is processed again, with `params`, from the
  // snapshot just before it; nullopt when no attempt on that chain was made.
  static std::optional<LoopAttempt> RetryLoopWith(const MapperParams& params) {
    LogRunner runner = *before_loop_;
    runner.SetParams(params);
    runner.Step();
    const LoopAttempt* a = AttemptFor(runner, loop_.log_index, loop_.chain_first);
    if (a == nullptr) return std::nullopt;
    return *a;
  }

  static std::shared_ptr<const io::LaserLog> log_;
  static std::unique_ptr<LogRunner> full_;
  static std::unique_ptr<LogRunner> before_loop_;
  static LoopAttempt loop_;
};

std::shared_ptr<const io::LaserLog> MapperOnCorridor::log_;
std::unique_ptr<LogRunner> MapperOnCorridor::full_;
std::unique_ptr<LogRunner> MapperOnCorridor::before_loop_;
LoopAttempt MapperOnCorridor::loop_;

TEST_F(MapperOnCorridor, RunSummaryIsConsistent) {
  const RunSummary s = full_->Summary();
  EXPECT_EQ(s.scans_read, static_cast<int>(log_->scans.size()));
  EXPECT_EQ(s.scans_offered, s.scans_read);
  EXPECT_EQ(s.nodes + s.scans_not_moved, s.scans_offered);
  EXPECT_EQ(s.edges[static_cast<int>(EdgeKind::kSequential)], s.nodes - 1);  // one per scan after the first
  EXPECT_GE(s.loop_closures.size(), 1u);
  EXPECT_EQ(s.solver_runs, static_cast<int>(s.loop_closures.size()));  // one solve per accepted loop
  EXPECT_EQ(full_->Trajectory().size(), log_->scans.size());
  EXPECT_EQ(s.laser_max_range, 30.0);  // the simulator's no-return value, under the 80 m cap
  EXPECT_EQ(s.range_threshold, 12.0);  // slam_karto rule
  // After a solve every scan's pose is the solver's node value (§7.1 write-back).
  const Mapper& m = full_->mapper();
  EXPECT_EQ(m.graph().node_values()[0], m.scans()[0].corrected_pose());  // node 0 fixed at its start
  EXPECT_EQ(m.scans()[0].corrected_pose(), log_->scans[0].laser_pose);
}

TEST_F(MapperOnCorridor, ForkedStateContinuesBitForBit) {
  LogRunner a = *before_loop_;
  LogRunner b = *before_loop_;
  a.RunToEnd();
  b.RunToEnd();
  testing::ExpectSameEngineState(a, b);
  testing::ExpectSameEngineState(a, *full_);  // and equal to the run that was never forked (determinism)
}

// Skipping near-chain matches the bound proves unable to link changes nothing: same poses,
// graph, loop attempts and trajectory as matching every near chain.
TEST(Mapper, SkippingUnlinkableNearChainsChangesNothingInTheOffice) {
  sim::SimulationOptions o;
  o.world = "office";
  o.seed = 1;
  const auto log = std::make_shared<const io::LaserLog>(sim::Simulate(o).log);
  LogRunner skipping(log, MapperParams{});
  LogRunner all(log, MapperParams{});
  all.set_skip_unlinkable_near_chains(false);
  skipping.RunToEnd();
  all.RunToEnd();
  const MapperCounters& c = skipping.mapper().counters();
  EXPECT_GT(c.near_chain_matches_skipped, 0) << "the office run skipped nothing";
  EXPECT_GT(c.near_chain_matches, c.near_chain_matches_skipped);
  EXPECT_EQ(all.mapper().counters().near_chain_matches_skipped, 0);
  EXPECT_GE(skipping.Summary().loop_closures.size(), 1u);
  testing::ExpectSameEngineState(skipping, all, /*same_skips=*/false);
}

TEST(Mapper, SkippingUnlinkableNearChainsChangesNothingOnAnIntelSlice) {
  const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/intel.clf.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not available: " << path;
  io::LaserLog whole = io::ReadCarmenLog(path);
  whole.scans.resize(std::min<std::size_t>(whole.scans.size(), 2500));  // first loop closure at scan 1835
  const auto log = std::make_shared<const io::LaserLog>(std::move(whole));
  LogRunner skipping(log, MapperParams{});
  LogRunner all(log, MapperParams{});
  all.set_skip_unlinkable_near_chains(false);
  skipping.RunToEnd();
  all.RunToEnd();
  EXPECT_GT(skipping.mapper().counters().near_chain_matches_skipped, 50);
  EXPECT_GE(skipping.Summary().loop_closures.size(), 1u);
  testing::ExpectSameEngineState(skipping, all, /*same_skips=*/false);
}

TEST_F(MapperOnCorridor, LoopParametersChangedOnACopyAffectOnlyLaterDecisions) {
  LogRunner same = *before_loop_;
  same.SetParams(testing::FastMapperParams());  // identical parameters: nothing changes
  LogRunner strict = *before_loop_;
  MapperParams p = testing::FastMapperParams();
  p.loop_match_minimum_chain_size = 100000;
  strict.SetParams(p);
  same.RunToEnd();
  strict.RunToEnd();
  testing::ExpectSameEngineState(same, *full_);
  const int loops_before = before_loop_->mapper().counters().loops_closed;
  EXPECT_EQ(strict.mapper().counters().loops_closed, loops_before);
  EXPECT_GT(full_->mapper().counters().loops_closed, loops_before);
}

TEST_F(MapperOnCorridor, CoarseResponseGateIsStrict) {
  const double s1 = loop_.coarse_response;
  MapperParams p = testing::FastMapperParams();
  p.loop_match_minimum_response_coarse = s1;  // s1 > p fails when equal
  std::optional<LoopAttempt> a = RetryLoopWith(p);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->coarse_response, s1);
  EXPECT_FALSE(a->coarse_passed);
  EXPECT_FALSE(a->accepted);

  p.loop_match_minimum_response_coarse = std::nextafter(s1, 0.0);
  a = RetryLoopWith(p);
  ASSERT_TRUE(a.has_value());
  EXPECT_TRUE(a->coarse_passed);
  EXPECT_TRUE(a->accepted);
}

TEST_F(MapperOnCorridor, CoarseVarianceGateUsesQSquared) {
  const double var = std::max(loop_.coarse_covariance(0, 0), loop_.coarse_covariance(1, 1));
  MapperParams p = testing::FastMapperParams();
  p.loop_match_maximum_variance_coarse = std::sqrt(var) * (1.0 - 1e-9);
  std::optional<LoopAttempt> a = RetryLoopWith(p);  // tight
  ASSERT_TRUE(a.has_value());
  EXPECT_FALSE(a->coarse_passed);
  p.loop_match_maximum_variance_coarse = std::sqrt(var) * (1.0 + 1e-9);
  a = RetryLoopWith(p);  // loose
  ASSERT_TRUE(a.has_value());
  EXPECT_TRUE(a->coarse_passed);
}

TEST_F(MapperOnCorridor, FineGateAcceptsEquality) {
  MapperParams p = testing::FastMapperParams();
  p.loop_match_minimum_response_fine = loop_.fine_response;  // s2 >= threshold accepts
  std::optional<LoopAttempt> a = RetryLoopWith(p);
  ASSERT_TRUE(a.has_value());
  EXPECT_TRUE(a->accepted);
  p.loop_match_minimum_response_fine = std::nextafter(loop_.fine_response, 1.0);
  a = RetryLoopWith(p);
  ASSERT_TRUE(a.has_value());
  EXPECT_FALSE(a->accepted);
}

// §6.1 quirk: with the closest chain member beyond LinkScanMaximumDistance the loop is accepted,
// no edge is added, and the solver still runs.
TEST_F(MapperOnCorridor, LoopAcceptedWithoutEdgeStillSolves) {
  LogRunner r = *before_loop_;
  MapperParams p = testing::FastMapperParams();
  p.link_scan_maximum_distance = 0.001;
  r.SetParams(p);
  const int solves_before = static_cast<int>(r.mapper().solver_runs().size());
  const int loop_edges_before = r.mapper().counters().edges_added[static_cast<int>(EdgeKind::kLoop)];
  const ProcessResult result = r.Step();
  const LoopAttempt* a = AttemptFor(r, loop_.log_index, loop_.chain_first);
  ASSERT_NE(a, nullptr);
  ASSERT_TRUE(a->accepted);
  EXPECT_EQ(a->linked_to, -1);
  EXPECT_EQ(r.mapper().counters().edges_added[static_cast<int>(EdgeKind::kLoop)], loop_edges_before);
  EXPECT_EQ(result.edges_added[static_cast<int>(EdgeKind::kLoop)], 0);
  EXPECT_EQ(static_cast<int>(r.mapper().solver_runs().size()), solves_before + result.loops_closed);
  EXPECT_GE(result.loops_closed, 1);
}

// The slam_toolbox back-end closes the same loop from the same state (its own solve).
TEST_F(MapperOnCorridor, CeresBackEndClosesTheSameLoop) {
  LogRunner r = *before_loop_;
  MapperParams p = testing::FastMapperParams();
  p.solver = SolverKind::kCeres;
  r.SetParams(p);
  const ProcessResult result = r.Step();
  ASSERT_GE(result.loops_closed, 1);
  EXPECT_EQ(r.mapper().solver_runs().back().backend, "ceres");
  EXPECT_TRUE(r.mapper().solver_runs().back().updated);
  const int id = result.state_id;
  LogRunner spa = *before_loop_;
  spa.Step();
  const Pose2 a = r.mapper().scans()[id].corrected_pose(), b = spa.mapper().scans()[id].corrected_pose();
  EXPECT_NEAR(a.x, b.x, 0.05);
  EXPECT_NEAR(a.y, b.y, 0.05);
}

TEST(Mapper, PoseIsOdometryWithoutScanMatching) {
  sim::SimulationOptions o;
  o.world = "corridor";
  o.speed_mps = 1.0;
  auto log = std::make_shared<const io::LaserLog>(sim::Simulate(o).log);
  MapperParams p;
  p.use_scan_matching = false;
  LogRunner runner(log, p);
  runner.RunToEnd();
  const auto trajectory = runner.Trajectory();
  ASSERT_EQ(trajectory.size(), log->scans.size());
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    EXPECT_NEAR(trajectory[k].pose.x, log->scans[k].laser_pose.x, 1e-9);
    EXPECT_NEAR(trajectory[k].pose.y, log->scans[k].laser_pose.y, 1e-9);
    EXPECT_NEAR(NormalizeAngle(trajectory[k].pose.theta - log->scans[k].laser_pose.theta), 0.0, 1e-9);
    EXPECT_EQ(trajectory[k].time, log->scans[k].ipc_time);
  }
  EXPECT_EQ(runner.mapper().graph().num_vertices(), 0);
  EXPECT_GT(runner.mapper().scans().size(), 10u);
  EXPECT_THROW(runner.SetParams(MapperParams{}), InputError);  // use_scan_matching is fixed now
}

TEST(Mapper, RejectsScansWithAnotherReadingCountAndStaysPut) {
  MapperParams p;
  Mapper mapper(p);
  auto geometry = std::make_shared<LaserGeometry>();
  geometry->angular_resolution = 0.1;
  geometry->num_readings = 3;
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{1, 1, 1});
  EXPECT_EQ(mapper.Process(LaserScan(geometry, ranges, {}, 0.0)).outcome, ProcessResult::Outcome::kProcessed);
  auto other = std::make_shared<LaserGeometry>(*geometry);
  other->num_readings = 2;
  auto two = std::make_shared<const std::vector<double>>(std::vector<double>{1, 1});
  EXPECT_EQ(mapper.Process(LaserScan(other, two, {1, 0, 0}, 0.0)).outcome, ProcessResult::Outcome::kWrongReadingCount);
  EXPECT_EQ(mapper.Process(LaserScan(geometry, ranges, {0.05, 0, 0}, 0.0)).outcome, ProcessResult::Outcome::kNotMoved);
  EXPECT_EQ(mapper.counters().scans_processed, 1);
  EXPECT_EQ(mapper.counters().scans_wrong_reading_count, 1);
  EXPECT_EQ(mapper.counters().scans_not_moved, 1);
}

// With one beam geometry per-geometry is the node's single laser, decision for decision.
TEST_F(MapperOnCorridor, PerGeometryWithOneGeometryIsTheNode) {
  io::LaserLog log = *log_;
  io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
  LogRunner per_geometry(std::make_shared<const io::LaserLog>(std::move(log)), testing::FastMapperParams());
  per_geometry.RunToEnd();
  EXPECT_EQ(per_geometry.lasers().geometries.size(), 1u);
  testing::ExpectSameEngineState(per_geometry, *full_);
}

TEST(Mapper, ConstructorValidatesParameters) {
  MapperParams p;
  p.loop_match_minimum_chain_size = 0;
  EXPECT_THROW(Mapper{p}, InputError);
}

}  // namespace
}  // namespace slamtune::slam
