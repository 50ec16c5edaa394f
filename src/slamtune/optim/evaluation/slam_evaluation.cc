#include "slamtune/optim/evaluation/slam_evaluation.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <optional>

#include "slamtune/common/error.h"
#include "slamtune/common/progress.h"
#include "slamtune/metrics/gt_error.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/occupancy_grid.h"

namespace slamtune::optim {
namespace {

slam::OccupancyGrid GridOf(const slam::LogRunner& runner, const slam::MapperParams& params) {
  return slam::OccupancyGrid::FromScans(std::span<const slam::LaserScan>(runner.mapper().scans()),
                                        slam::GridOptionsOf(params));
}

// Gives a run's correlative search the evaluation slots left idle (SlamEvaluationContext::
// idle_slots) as threads, checked every few scans; the results do not depend on it.
class IdleSlotThreads {
 public:
  IdleSlotThreads(const SlamEvaluationContext& context, const slam::MapperParams& params)
      : idle_(context.idle_slots), params_(params) {}
  void Update(slam::LogRunner& runner) {
    if (!idle_ || ++steps_ % kEvery != 0) return;
    const int want = 1 + std::max(0, idle_->load());
    if (want == params_.matcher_threads) return;
    params_.matcher_threads = want;
    runner.SetParams(params_);
  }

 private:
  static constexpr int kEvery = 16;
  std::shared_ptr<const std::atomic<int>> idle_;
  slam::MapperParams params_;
  int steps_ = 0;
};

slam::LogRunner RunToEnd(const SlamEvaluationContext& context, const slam::MapperParams& params,
                         const RunObservers& observers = {}) {
  SLAMTUNE_CHECK(context.log != nullptr);
  slam::LogRunner runner(context.log, params, context.shared_work);
  if (observers.trace) runner.set_trace(observers.trace);
  IdleSlotThreads threads(context, params);
  while (!runner.Done()) {
    runner.Step();
    threads.Update(runner);
    if (observers.after_step) observers.after_step(runner);
  }
  return runner;
}

// Steps `runner` until the end of the log or a break of its front end (slam::BreakWatch);
// returns why it stopped early, or nullopt.
std::optional<std::string> RunUntilBreak(const SlamEvaluationContext& context, const slam::MapperParams& params,
                                         slam::LogRunner& runner) {
  slam::BreakWatch watch;
  IdleSlotThreads threads(context, params);
  std::size_t seen = 0;
  while (!runner.Done()) {
    runner.Step();
    threads.Update(runner);
    const std::vector<slam::SequentialMatchStep>& steps = runner.sequential_matches();
    if (steps.size() == seen) continue;
    seen = steps.size();
    const std::optional<std::size_t> broke = watch.Add(steps);
    if (!broke) continue;
    const slam::SequentialMatchStep& s = steps[*broke];
    return fmt::format(
        "stopped at log scan {} of {}: the front end broke at log scan {} ({:.1f} s into the log; the "
        "match ran out of search room {} with response {:.2f} and the matches after it did not undo "
        "it)",
        runner.next_index(), runner.size(), s.log_index, s.time, s.at_heading_edge ? "in heading" : "in position",
        s.response);
  }
  return std::nullopt;
}

// The record of a finished run: its map (or the map score of the same final state scored before),
// objectives and errors. `run_out` (may be null) receives the run.
EvaluationRecord Score(const SlamEvaluationContext& context, const Assignment& assignment,
                       const slam::MapperParams& params, const slam::LogRunner& runner,
                       std::chrono::steady_clock::time_point start, SlamRun* run_out) {
  SlamRun run;
  run.summary = runner.Summary();
  run.trajectory = runner.Trajectory();
  if (run_out != nullptr) {
    run.sequential_matches = runner.sequential_matches();
    run.front_end = slam::AssessFrontEnd(run.sequential_matches);
    run.lasers = runner.lasers();
    run.range_threshold = runner.mapper().range_threshold();
  }
  const auto map_start = std::chrono::steady_clock::now();
  // The map and its scores, or those of the same final state scored before (run_out wants the map).
  std::optional<MapScores> scores;
  std::vector<std::uint64_t> key;
  const bool use_cache = context.map_scores != nullptr && run_out == nullptr;
  if (use_cache) {
    key = MapScoreCache::KeyOf(slam::GridOptionsOf(params), std::span<const slam::LaserScan>(runner.mapper().scans()));
    scores = context.map_scores->Find(key);
  }
  if (!scores) {
    const slam::OccupancyGrid grid = GridOf(runner, params);
    run.map = grid.ToMapImage();
    scores.emplace();
    scores->grid = grid.summary();
    scores->quality = metrics::ComputeMapQuality(run.map, context.metrics);
    if (!context.relations.empty()) scores->error = metrics::ComputeGtError(run.trajectory, context.relations);
    if (context.trajectory_map) scores->drawn = context.trajectory_map->Draw(run.trajectory).summary();
    if (use_cache) context.map_scores->Insert(std::move(key), *scores);
  }
  const metrics::MapQuality& quality = scores->quality;
  run.quality = scores->quality;
  run.error = scores->error;
  run.map_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - map_start).count();

  EvaluationRecord record;
  record.params = assignment;
  record.occupied_ratio = quality.occupied_ratio;
  record.corner_pixels = static_cast<double>(quality.corner_pixels);
  record.enclosed_areas = quality.enclosed_areas;
  record.occupied_ratio_known = quality.occupied_ratio_known;
  record.corners = quality.corners;
  record.contours = quality.contours;
  record.occupied_cells = static_cast<double>(quality.occupied_cells);
  record.hits = static_cast<double>(scores->grid.hits);
  record.hits_in_free_cells = static_cast<double>(scores->grid.hits_in_free_cells);
  record.hits_in_unknown_cells = static_cast<double>(scores->grid.hits_in_unknown_cells);
  record.drawn_wall_cells = static_cast<double>(scores->drawn.occupied_cells);
  record.nodes = run.summary.nodes;
  record.loop_closures = static_cast<int>(run.summary.loop_closures.size());
  for (const auto& loop : run.summary.loop_closures) record.loop_scans.push_back(loop.log_index);
  if (!context.relations.empty()) {
    const metrics::GtError& error = scores->error;
    record.has_gt = error.relations_used > 0;
    record.trans_mean_m = error.trans_mean_m;
    record.trans_std_m = error.trans_std_m;
    record.rot_mean_deg = error.rot_mean_deg;
    record.rot_std_deg = error.rot_std_deg;
    record.relations_used = static_cast<int>(error.relations_used);
  }
  if (quality.occupied_cells == 0) {
    // Nothing to score: an empty map would win every objective.
    record.status = RunStatus::kFailed;
    record.reason =
        "the map has no occupied cell (no reading reached it: min_laser_range at or above the range "
        "threshold?)";
  }
  record.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (run_out != nullptr) *run_out = std::move(run);
  return record;
}

}  // namespace

slam::MapperParams SlamEvaluationContext::ParamsFor(const Assignment& assignment) const {
  slam::MapperParams params = base;
  slam::SetNumerics(params, assignment);
  return params;
}

EvaluationRecord EvaluateSlam(const SlamEvaluationContext& context, const Assignment& assignment, SlamRun* run_out,
                              const RunObservers& observers) {
  const auto start = std::chrono::steady_clock::now();
  const slam::MapperParams params = context.ParamsFor(assignment);
  // The base configuration itself is always mapped to the end: every answer is judged against it.
  const bool observed = observers.after_step || observers.trace;
  if (context.stop_broken_runs && run_out == nullptr && !observed && !(params == context.base)) {
    slam::LogRunner watched(context.log, params, context.shared_work);
    if (std::optional<std::string> broke = RunUntilBreak(context, params, watched)) {
      EvaluationRecord failed = EvaluationRecord::Failed("", assignment, *broke);
      failed.nodes = watched.mapper().counters().scans_processed;
      failed.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return failed;
    }
    return Score(context, assignment, params, watched, start, nullptr);
  }
  const slam::LogRunner runner = RunToEnd(context, params, observers);
  return Score(context, assignment, params, runner, start, run_out);
}

CandidateMap RenderSlamMap(const SlamEvaluationContext& context, const Assignment& assignment) {
  const slam::MapperParams params = context.ParamsFor(assignment);
  const slam::LogRunner runner = RunToEnd(context, params);
  CandidateMap out;
  out.map = GridOf(runner, params).ToMapImage();
  const std::vector<slam::LaserScan>& scans = runner.mapper().scans();
  const auto valid = [&](int id) { return id >= 0 && static_cast<std::size_t>(id) < scans.size(); };
  for (const slam::LoopClosureRecord& loop : runner.Summary().loop_closures) {
    const int from = loop.linked_to >= 0 ? loop.linked_to : loop.chain_first;
    if (!valid(from) || !valid(loop.node)) continue;
    const Pose2& a = scans[static_cast<std::size_t>(from)].corrected_pose();
    const Pose2& b = scans[static_cast<std::size_t>(loop.node)].corrected_pose();
    out.loop_edges.push_back({a.x, a.y, b.x, b.y, loop.log_index});
  }
  out.path.reserve(scans.size());
  for (const slam::LaserScan& scan : scans) out.path.emplace_back(scan.corrected_pose().x, scan.corrected_pose().y);
  return out;
}

WallDrawing WallDrawingFor(const ObjectiveSet& objectives) {
  return objectives.Uses(Objective("drawn_wall_cells")) ? WallDrawing::kDraw : WallDrawing::kSkip;
}

void DrawWall(SlamEvaluationContext& context, WallDrawing drawing) {
  SLAMTUNE_CHECK(context.log != nullptr);
  if (drawing == WallDrawing::kSkip) {
    context.trajectory_map = nullptr;
  } else if (context.trajectory_map == nullptr) {
    context.trajectory_map = std::make_shared<const metrics::TrajectoryMap>(context.log, context.base);
  }
}

void ShareWork(SlamEvaluationContext& context, std::size_t share_mb) {
  SLAMTUNE_CHECK(share_mb > 0);
  slam::MatchCacheOptions options;
  options.byte_budget = share_mb << 20;
  slam::SharedWork& work = context.shared_work;
  work.match_cache = std::make_shared<slam::MatchCache>(options);
  work.solve_cache = std::make_shared<slam::SolveCache>(std::max<std::size_t>(share_mb << 19, 1 << 20));
  context.map_scores = std::make_shared<MapScoreCache>(std::max<std::size_t>(share_mb << 18, 1 << 20));
  work.barycenter_cache = std::make_shared<slam::BarycenterCache>(std::max<std::size_t>(share_mb << 17, 1 << 20));
}

std::string SharedWorkReport(const SlamEvaluationContext& context) {
  const slam::SharedWork& work = context.shared_work;
  if (!work.match_cache) return "match cache: off (--no-share)";
  std::string out = work.match_cache->counters().ToString();
  for (const std::string& line : {work.solve_cache ? work.solve_cache->counters().ToString() : "",
                                  work.barycenter_cache ? work.barycenter_cache->counters().ToString() : "",
                                  context.map_scores ? context.map_scores->counters().ToString() : ""}) {
    if (!line.empty()) out.append(1, '\n').append(line);
  }
  return out;
}

std::string SharedWorkBrief(const SlamEvaluationContext& context) {
  if (!context.shared_work.match_cache) return "";
  const slam::MatchCacheCounters c = context.shared_work.match_cache->counters();
  const std::uint64_t calls = c.hits + c.waits + c.misses;
  if (calls == 0) return "";
  return fmt::format("matches: {:.1f}% of {} shared, {} computed",
                     100.0 * static_cast<double>(c.hits + c.waits) / calls, FormatCount(static_cast<double>(calls)),
                     FormatCount(static_cast<double>(c.misses)));
}

}  // namespace slamtune::optim
