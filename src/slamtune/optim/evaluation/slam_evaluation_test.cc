#include "slamtune/optim/evaluation/slam_evaluation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <utility>

#include "slamtune/common/testing/same_bits.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::optim {
namespace {

using slamtune::testing::SameBits;

std::uint64_t Bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// `n` (r, g) sets as the optimiser's initial population spans them: r uniform in [2, 6] m,
// g an integer in [6, 20], from a fixed seed, plus the base fixed parameters.
std::vector<Assignment> RandomSets(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r(2.0, 6.0);
  std::uniform_int_distribution<int> g(6, 20);
  std::vector<Assignment> sets;
  for (int i = 0; i < n; ++i) {
    sets.push_back({{"loop_search_maximum_distance", r(rng)},
                    {"loop_match_minimum_chain_size", static_cast<double>(g(rng))},
                    {"loop_match_minimum_response_coarse", 0.7},
                    {"loop_match_maximum_variance_coarse", 0.4}});
  }
  return sets;
}

struct Evaluated {
  EvaluationRecord record;
  SlamRun run;
};

// Evaluates every set: without a cache one by one, with a cache on `threads` threads at once.
std::vector<Evaluated> EvaluateAll(const SlamEvaluationContext& context, const std::vector<Assignment>& sets,
                                   int threads) {
  std::vector<Evaluated> out(sets.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < sets.size(); i = next++)
      out[i].record = EvaluateSlam(context, sets[i], &out[i].run);
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  return out;
}

void ExpectIdentical(const Evaluated& a, const Evaluated& b, const std::string& label) {
  SCOPED_TRACE(label);
  const std::vector<double> fa = ObjectiveSet(ObjectiveSetKind::kPaper).Score(a.record);
  const std::vector<double> fb = ObjectiveSet(ObjectiveSetKind::kPaper).Score(b.record);
  EXPECT_EQ(Bits(a.record.hits_in_free_cells), Bits(b.record.hits_in_free_cells));
  EXPECT_EQ(Bits(a.record.hits_in_unknown_cells), Bits(b.record.hits_in_unknown_cells));
  ASSERT_EQ(fa.size(), fb.size());
  for (std::size_t k = 0; k < fa.size(); ++k) EXPECT_EQ(Bits(fa[k]), Bits(fb[k])) << "objective " << k;
  EXPECT_EQ(Bits(a.record.occupied_ratio_known), Bits(b.record.occupied_ratio_known));
  EXPECT_EQ(Bits(a.record.corners), Bits(b.record.corners));
  EXPECT_EQ(Bits(a.record.contours), Bits(b.record.contours));
  EXPECT_EQ(a.record.nodes, b.record.nodes);
  EXPECT_EQ(a.record.loop_scans, b.record.loop_scans);
  // Loop closures: scans, chains and responses.
  const auto& la = a.run.summary.loop_closures;
  const auto& lb = b.run.summary.loop_closures;
  ASSERT_EQ(la.size(), lb.size());
  for (std::size_t k = 0; k < la.size(); ++k) {
    EXPECT_EQ(la[k].log_index, lb[k].log_index);
    EXPECT_EQ(la[k].chain_first, lb[k].chain_first);
    EXPECT_EQ(la[k].chain_last, lb[k].chain_last);
    EXPECT_EQ(la[k].linked_to, lb[k].linked_to);
    EXPECT_EQ(Bits(la[k].coarse_response), Bits(lb[k].coarse_response));
    EXPECT_EQ(Bits(la[k].fine_response), Bits(lb[k].fine_response));
    EXPECT_EQ(Bits(la[k].coarse_var_xx), Bits(lb[k].coarse_var_xx));
  }
  EXPECT_EQ(a.run.summary.loop_attempts, b.run.summary.loop_attempts);
  EXPECT_EQ(a.run.summary.edges, b.run.summary.edges);
  // Every pose, bit for bit.
  ASSERT_EQ(a.run.trajectory.size(), b.run.trajectory.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.run.trajectory.size(); ++i) {
    if (!SameBits(a.run.trajectory[i].pose, b.run.trajectory[i].pose)) ++differing;
  }
  EXPECT_EQ(differing, 0u) << "poses differing";
  // The map, pixel for pixel.
  EXPECT_EQ(a.run.map.width, b.run.map.width);
  EXPECT_EQ(a.run.map.height, b.run.map.height);
  EXPECT_EQ(a.run.map.origin, b.run.map.origin);
  EXPECT_TRUE(a.run.map.pixels == b.run.map.pixels) << "map pixels differ";
}

void ExpectSameRecord(const EvaluationRecord& a, const EvaluationRecord& b, const std::string& label) {
  SCOPED_TRACE(label);
  const std::vector<double> fa = ObjectiveSet(ObjectiveSetKind::kPaper).Score(a),
                            fb = ObjectiveSet(ObjectiveSetKind::kPaper).Score(b);
  for (std::size_t k = 0; k < fa.size(); ++k) EXPECT_EQ(Bits(fa[k]), Bits(fb[k])) << "objective " << k;
  EXPECT_EQ(Bits(a.occupied_ratio_known), Bits(b.occupied_ratio_known));
  EXPECT_EQ(Bits(a.corners), Bits(b.corners));
  EXPECT_EQ(Bits(a.contours), Bits(b.contours));
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.loop_scans, b.loop_scans);
  EXPECT_EQ(a.has_gt, b.has_gt);
  EXPECT_EQ(Bits(a.trans_mean_m), Bits(b.trans_mean_m));
  EXPECT_EQ(Bits(a.rot_std_deg), Bits(b.rot_std_deg));
  EXPECT_EQ(a.relations_used, b.relations_used);
}

// The invariant of the shared cache: a batch evaluated concurrently with it equals the same
// batch evaluated one by one without it, and the cache did serve matches.
// `min_loop_lists`: distinct loop-closure lists the sets must produce, so that the check covers
// runs whose decisions diverge (and stop sharing) part-way.
void CheckSharingChangesNothing(std::shared_ptr<const io::LaserLog> log, int sets, unsigned seed,
                                const std::string& label, std::size_t min_loop_lists) {
  SlamEvaluationContext plain;
  plain.log = std::move(log);
  SlamEvaluationContext shared = plain;
  shared.shared_work.match_cache = std::make_shared<slam::MatchCache>();
  shared.shared_work.solve_cache = std::make_shared<slam::SolveCache>();
  shared.shared_work.barycenter_cache = std::make_shared<slam::BarycenterCache>();
  const std::vector<Assignment> batch = RandomSets(sets, seed);
  const std::vector<Evaluated> without = EvaluateAll(plain, batch, 1);
  const std::vector<Evaluated> with = EvaluateAll(shared, batch, 3);
  std::set<std::vector<int>> loop_lists;
  std::size_t loops = 0;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    ExpectIdentical(without[i], with[i], label + " set " + std::to_string(i));
    loop_lists.insert(without[i].record.loop_scans);
    loops += without[i].record.loop_scans.size();
  }
  const slam::MatchCacheCounters c = shared.shared_work.match_cache->counters();
  EXPECT_GT(c.hits + c.waits, 0u) << label << ": the cache served nothing";
  EXPECT_EQ(c.bypassed, 0u);
  EXPECT_GE(loop_lists.size(), min_loop_lists) << label << ": the sets did not diverge";
  EXPECT_GT(shared.shared_work.barycenter_cache->counters().hits, 0u) << label << ": no barycentre was shared";

  // Map scores shared too (the optimiser's path: records only). Twice, so that the second pass
  // is served from the map-score cache entirely.
  shared.map_scores = std::make_shared<MapScoreCache>();
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<EvaluationRecord> records(batch.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t i = next++; i < batch.size(); i = next++) records[i] = EvaluateSlam(shared, batch[i]);
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < 3; ++t) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
    for (std::size_t i = 0; i < batch.size(); ++i) {
      ExpectSameRecord(without[i].record, records[i],
                       label + " map scores pass " + std::to_string(pass) + " set " + std::to_string(i));
    }
  }
  const MapScoreCacheCounters m = shared.map_scores->counters();
  EXPECT_GE(m.hits, batch.size()) << label << ": the second pass was not served from the map-score cache";
  // Sets with other (r, g) but the same outcome share one entry.
  std::set<std::vector<std::uint64_t>> final_states;
  for (const Evaluated& e : without) {
    std::vector<std::uint64_t> state;
    for (const auto& p : e.run.trajectory) {
      state.push_back(Bits(p.pose.x));
      state.push_back(Bits(p.pose.y));
      state.push_back(Bits(p.pose.theta));
    }
    final_states.insert(state);
  }
  EXPECT_EQ(m.entries, final_states.size()) << label << ": one entry per distinct final state";
  const slam::CacheCounters sc = shared.shared_work.solve_cache->counters();
  if (loops > 0) {
    EXPECT_GT(sc.hits, 0u) << label << ": no solve was shared";
  }
  std::printf("%s: %zu scans, %zu loop closures, %zu distinct loop-closure lists over %zu sets; %s; %s; %s; %s\n",
              label.c_str(), plain.log->scans.size(), loops, loop_lists.size(), batch.size(), c.ToString().c_str(),
              sc.ToString().c_str(), m.ToString().c_str(),
              shared.shared_work.barycenter_cache->counters().ToString().c_str());
}

// The first `scans` scans of a built-in world, with the world's relations.
SlamEvaluationContext WorldContext(const std::string& world, std::size_t scans) {
  sim::SimulationOptions o;
  o.world = world;
  sim::Simulation s = sim::Simulate(o);
  s.log.scans.resize(std::min(s.log.scans.size(), scans));
  SlamEvaluationContext context;
  context.log = std::make_shared<const io::LaserLog>(std::move(s.log));
  context.relations = std::move(s.relations);
  return context;
}

std::shared_ptr<const io::LaserLog> WorldSlice(const std::string& world, std::size_t scans) {
  return WorldContext(world, scans).log;
}

// A map no reading reached would win every objective: it is a failed run, with the reason.
TEST(SlamEvaluation, AnEmptyMapIsAFailedRun) {
  SlamEvaluationContext context;
  context.log = WorldSlice("office", 200);
  context.base.min_laser_range = 30.0;  // above every reading
  const EvaluationRecord r = EvaluateSlam(context, {{"loop_search_maximum_distance", 4.0}});
  EXPECT_EQ(r.status, RunStatus::kFailed);
  EXPECT_NE(r.reason.find("no occupied cell"), std::string::npos) << r.reason;
  context.base.min_laser_range = 0.0;
  EXPECT_EQ(EvaluateSlam(context, {{"loop_search_maximum_distance", 4.0}}).status, RunStatus::kOk);
}

// The drawn wall (objective n_w) is counted only when asked for, and it ranks runs of other node
// spacings by their error where the run's own map cannot: sparser nodes draw fewer scans into
// their own map, so it shrinks, while the same scans of the log drawn along the sparser, worse
// path make more wall.
TEST(SlamEvaluation, TheDrawnWallRanksNodeSpacingsByTheirError) {
  SlamEvaluationContext context = WorldContext("office", 1200);
  const Assignment dense_set = {{"minimum_travel_distance", 0.2}};
  const Assignment sparse_set = {{"minimum_travel_distance", 1.5}, {"minimum_travel_heading", 1.0}};
  EXPECT_EQ(EvaluateSlam(context, dense_set).drawn_wall_cells, 0.0);
  DrawWall(context, WallDrawing::kDraw);
  ASSERT_NE(context.trajectory_map, nullptr);
  const EvaluationRecord dense = EvaluateSlam(context, dense_set);
  const EvaluationRecord sparse = EvaluateSlam(context, sparse_set);
  ASSERT_EQ(dense.status, RunStatus::kOk);
  ASSERT_EQ(sparse.status, RunStatus::kOk);
  ASSERT_TRUE(dense.has_gt && sparse.has_gt);
  std::printf("error %.4f -> %.4f m; own map %.0f -> %.0f cells; drawn wall %.0f -> %.0f cells\n", dense.trans_mean_m,
              sparse.trans_mean_m, dense.occupied_cells, sparse.occupied_cells, dense.drawn_wall_cells,
              sparse.drawn_wall_cells);
  ASSERT_GT(sparse.trans_mean_m, dense.trans_mean_m * 1.2) << "the sparse run is not worse: the test checks nothing";
  EXPECT_LT(sparse.occupied_cells, dense.occupied_cells);      // the own map calls the worse run cleaner
  EXPECT_GT(sparse.drawn_wall_cells, dense.drawn_wall_cells);  // the drawn wall does not
  DrawWall(context, WallDrawing::kSkip);
  EXPECT_EQ(context.trajectory_map, nullptr);
}

// In a front-end search a run whose own matches show a break is stopped there and recorded as
// failed with where it broke; a run that holds, and the base configuration itself (always run
// to the end, the reference of every answer), are scored as before.
TEST(SlamEvaluation, ABrokenFrontEndStopsTheRunWhenAsked) {
  // The jump is 20 m into the route (near scan 200): the first 700 scans hold the break and as
  // much drive again after it, at a third of the whole world's cost.
  SlamEvaluationContext context = WorldContext("office-jump", 700);
  const Assignment base = {{"correlation_search_space_dimension", 0.3}};
  const Assignment broken = {{"correlation_search_space_dimension", 0.32}};  // still far too small for 1 m
  const Assignment wide = {{"correlation_search_space_dimension", 1.6}};
  const EvaluationRecord broken_full = EvaluateSlam(context, broken);
  ASSERT_EQ(broken_full.status, RunStatus::kOk);
  context.stop_broken_runs = true;
  const EvaluationRecord stopped = EvaluateSlam(context, broken);
  EXPECT_EQ(stopped.status, RunStatus::kFailed);
  EXPECT_NE(stopped.reason.find("the front end broke at log scan"), std::string::npos) << stopped.reason;
  EXPECT_LT(stopped.nodes, broken_full.nodes / 2);  // stopped early, at the jump
  const EvaluationRecord base_record = EvaluateSlam(context, base);
  EXPECT_EQ(base_record.status, RunStatus::kOk);
  context.stop_broken_runs = false;
  const EvaluationRecord wide_full = EvaluateSlam(context, wide);
  context.stop_broken_runs = true;
  const EvaluationRecord wide_watched = EvaluateSlam(context, wide);
  ASSERT_EQ(wide_watched.status, RunStatus::kOk) << wide_watched.reason;
  EXPECT_TRUE(SameBits(wide_watched.trans_mean_m, wide_full.trans_mean_m));
  EXPECT_EQ(wide_watched.loop_closures, wide_full.loop_closures);
  EXPECT_TRUE(SameBits(wide_watched.corner_pixels, wide_full.corner_pixels));
}

// A run that takes idle evaluation slots as threads of its correlative search gives the same bits.
TEST(SlamEvaluation, IdleSlotsChangeNoResult) {
  SlamEvaluationContext context;
  context.log = WorldSlice("office", 400);
  const Assignment wide = {{"correlation_search_space_dimension", 1.2}};
  const EvaluationRecord alone = EvaluateSlam(context, wide);
  auto idle = std::make_shared<std::atomic<int>>(1);
  context.idle_slots = idle;
  const EvaluationRecord helped = EvaluateSlam(context, wide);
  ASSERT_EQ(alone.status, RunStatus::kOk);
  EXPECT_TRUE(SameBits(helped.corner_pixels, alone.corner_pixels));
  EXPECT_TRUE(SameBits(helped.occupied_ratio, alone.occupied_ratio));
  EXPECT_TRUE(SameBits(helped.hits_in_free_cells, alone.hits_in_free_cells));
  EXPECT_EQ(helped.loop_closures, alone.loop_closures);
  EXPECT_EQ(helped.nodes, alone.nodes);
}

// The report's map of a parameter set carries one loop edge per loop closure of its evaluation,
// both ends inside the map.
TEST(SlamEvaluation, RenderedMapCarriesTheLoopClosuresAsEdges) {
  SlamEvaluationContext context;
  context.log = WorldSlice("office", 1200);
  const Assignment set = {{"loop_search_maximum_distance", 5.0}, {"loop_match_minimum_chain_size", 6.0}};
  const EvaluationRecord record = EvaluateSlam(context, set);
  const CandidateMap rendered = RenderSlamMap(context, set);
  ASSERT_GT(record.loop_closures, 0) << "the slice closes no loop: the test checks nothing";
  EXPECT_EQ(rendered.loop_edges.size(), static_cast<std::size_t>(record.loop_closures));
  EXPECT_EQ(rendered.path.size(), static_cast<std::size_t>(record.nodes));
  for (std::size_t k = 0; k < rendered.loop_edges.size(); ++k) {
    EXPECT_EQ(rendered.loop_edges[k].log_index, record.loop_scans[k]);
  }
  const io::MapImage& m = rendered.map;
  ASSERT_GT(m.width, 0);
  const auto inside = [&](double x, double y) {
    return x >= m.origin.x && x <= m.origin.x + m.width * m.resolution && y >= m.origin.y &&
           y <= m.origin.y + m.height * m.resolution;
  };
  for (const LoopEdge& e : rendered.loop_edges) {
    EXPECT_TRUE(inside(e.from_x, e.from_y)) << e.from_x << ", " << e.from_y;
    EXPECT_TRUE(inside(e.to_x, e.to_y)) << e.to_x << ", " << e.to_y;
    EXPECT_GT(std::hypot(e.to_x - e.from_x, e.to_y - e.from_y), 0.0);
  }
}

TEST(SlamEvaluationShared, OfficeWorldResultsIdenticalWithTheCache) {
  CheckSharingChangesNothing(WorldSlice("office", 1200), 6, 11, "office", 3);
}

TEST(SlamEvaluationShared, CorridorWorldResultsIdenticalWithTheCache) {
  CheckSharingChangesNothing(WorldSlice("corridor", 100000), 6, 12, "corridor", 1);
}

TEST(SlamEvaluationShared, MitCsailSliceResultsIdenticalWithTheCache) {
  const std::filesystem::path path = std::filesystem::path(SLAMTUNE_DATASETS_DIR) / "mit-csail.clf.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "dataset not found: " << path;
  auto log = std::make_shared<io::LaserLog>(io::ReadCarmenLog(path.string()));
  log->scans.resize(std::min<std::size_t>(log->scans.size(), 400));
  CheckSharingChangesNothing(log, 6, 13, "mit-csail", 1);
}

}  // namespace
}  // namespace slamtune::optim
