#include "slamtune/metrics/trajectory_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::metrics {
namespace {

std::shared_ptr<const io::LaserLog> OfficeLog(sim::Simulation* out = nullptr) {
  sim::SimulationOptions options;
  options.world = "office";
  sim::Simulation s = sim::Simulate(options);
  auto log = std::make_shared<const io::LaserLog>(s.log);
  if (out != nullptr) *out = std::move(s);
  return log;
}

double OverruledShare(const slam::OccupancyGridSummary& s) {
  return static_cast<double>(s.hits_in_free_cells + s.hits_in_unknown_cells) / static_cast<double>(s.hits);
}

TEST(TrajectoryMap, DrawsAScanAfterEachStepOfOdometricTravelOrTurn) {
  const auto log = OfficeLog();
  TrajectoryMapOptions options;
  options.min_travel_m = 0.25;
  options.min_turn_rad = 0.2;
  const TrajectoryMap map(log, slam::MapperParams{}, options);
  const auto& chosen = map.scan_indices();
  ASSERT_GT(chosen.size(), 10u);
  EXPECT_LT(chosen.size(), log->scans.size());
  EXPECT_EQ(chosen.front(), 0u);
  for (std::size_t k = 1; k < chosen.size(); ++k) {
    const Pose2& a = log->scans[chosen[k - 1]].robot_pose;
    const Pose2& b = log->scans[chosen[k]].robot_pose;
    const bool moved = std::hypot(b.x - a.x, b.y - a.y) >= options.min_travel_m ||
                       std::fabs(NormalizeAngle(b.theta - a.theta)) >= options.min_turn_rad;
    EXPECT_TRUE(moved) << "scan " << chosen[k];
    EXPECT_GT(chosen[k], chosen[k - 1]);
  }
}

TEST(TrajectoryMap, WithoutAStepEveryScanIsDrawn) {
  const auto log = OfficeLog();
  TrajectoryMapOptions options;
  options.min_travel_m = 0.0;
  options.min_turn_rad = 0.0;
  EXPECT_EQ(TrajectoryMap(log, slam::MapperParams{}, options).scan_indices().size(), log->scans.size());
}

// A laser whose odd scans keep every other beam (at their own angles): the node's single laser
// skips them, --beams per-geometry draws them with a laser of their own (docs/engine.md §3.5).
TEST(TrajectoryMap, PerGeometryDrawsEveryScanWithItsOwnLaser) {
  sim::Simulation s;
  io::LaserLog log = *OfficeLog(&s);
  for (std::size_t i = 1; i < log.scans.size(); i += 2) {
    io::LaserScanRecord& scan = log.scans[i];
    std::vector<double> kept;
    for (std::size_t b = 0; b < scan.ranges.size(); b += 2) kept.push_back(scan.ranges[b]);
    scan.ranges = kept;
    scan.angle_increment *= 2.0;
  }
  TrajectoryMapOptions every;
  every.min_travel_m = 0.0;
  every.min_turn_rad = 0.0;
  io::LaserLog node = log;
  io::HarmonizeBeams(io::BeamPolicy::kNode, &node);
  io::HarmonizeBeams(io::BeamPolicy::kPerGeometry, &log);
  const TrajectoryMap one(std::make_shared<const io::LaserLog>(std::move(node)), slam::MapperParams{}, every);
  const TrajectoryMap two(std::make_shared<const io::LaserLog>(std::move(log)), slam::MapperParams{}, every);
  EXPECT_EQ(one.scan_indices().size(), (s.log.scans.size() + 1) / 2);
  EXPECT_EQ(two.scan_indices().size(), s.log.scans.size());
  const slam::OccupancyGridSummary drawn = two.Draw(s.truth).summary();
  EXPECT_GT(drawn.hits, one.Draw(s.truth).summary().hits);
  EXPECT_LT(OverruledShare(drawn), 0.10);  // the thinned scans' beams land on the same walls
}

// The figures the objectives read must rank a broken trajectory worse than the true one: a
// heading error planted halfway draws every later wall a second time, beside the first.
TEST(TrajectoryMap, ABrokenTrajectoryDrawsMoreWallAndOverrulesMoreEndPoints) {
  sim::Simulation s;
  const auto log = OfficeLog(&s);
  const TrajectoryMap map(log, slam::MapperParams{}, {});
  std::vector<io::TimedPose> broken = s.truth;
  const std::size_t half = broken.size() / 2;
  const Pose2 pivot = broken[half].pose;
  const Pose2 turn{0.0, 0.0, 0.08};  // 4.6 degrees about the pose at the break
  for (std::size_t i = half; i < broken.size(); ++i) {
    broken[i].pose = Compose(Compose(pivot, turn), Between(pivot, broken[i].pose));
  }
  const slam::OccupancyGridSummary truth = map.Draw(s.truth).summary();
  const slam::OccupancyGridSummary bad = map.Draw(broken).summary();
  EXPECT_GT(bad.occupied_cells, truth.occupied_cells * 11 / 10);
  EXPECT_GT(OverruledShare(bad), OverruledShare(truth) + 0.02);
  EXPECT_LT(OverruledShare(truth), 0.10);
}

// Whatever the node spacing of the run, the same scans are drawn: a trajectory with the same
// pose for each log scan gives the same counts (here: drawing twice).
TEST(TrajectoryMap, TheSameTrajectoryGivesTheSameCounts) {
  sim::Simulation s;
  const auto log = OfficeLog(&s);
  const TrajectoryMap map(log, slam::MapperParams{}, {});
  const slam::OccupancyGridSummary a = map.Draw(s.truth).summary();
  const slam::OccupancyGridSummary b = map.Draw(s.truth).summary();
  EXPECT_EQ(a.occupied_cells, b.occupied_cells);
  EXPECT_EQ(a.hits, b.hits);
  EXPECT_EQ(a.hits_in_free_cells, b.hits_in_free_cells);
  EXPECT_EQ(a.scans, static_cast<int>(map.scan_indices().size()));
}

TEST(TrajectoryMap, RefusesANegativeOrNonFiniteStep) {
  const auto log = OfficeLog();
  TrajectoryMapOptions options;
  options.min_travel_m = -0.1;
  EXPECT_THROW(TrajectoryMap(log, slam::MapperParams{}, options), InputError);
  options = {};
  options.min_turn_rad = std::nan("");
  EXPECT_THROW(TrajectoryMap(log, slam::MapperParams{}, options), InputError);
}

}  // namespace
}  // namespace slamtune::metrics
