// Speed of the correlative scan matcher and the occupancy grid (docs/engine.md §4, §8).
//
//   bench_matcher [--benchmark_filter=...]
//
// Input: the first 900 scans of /work/shared/datasets/intel.clf.gz (every third kept, about
// the spacing of processed scans), or, if the dataset is absent, synthetic 180-beam scans of
// a room along a loop. Cases:
//   * Sequential: a scan against the 70 scans before it (a full running buffer), penalised
//     and refined, with the slam_karto sequential matcher (§4.1 first row).
//   * SequentialUnpenalised: against the 20 scans before it, no penalty, refined (how near
//     chains and the loop "fine" check use the sequential matcher).
//   * LoopCoarse: a scan against a 12-scan chain with the loop matcher, 81x81x21 poses,
//     no penalty, no refinement (§6.1 coarse gate); with 1 or 2 threads and branch and bound
//     on or off.
//   * Reference*: the same with ReferenceScanMatcher, a plain transcription of Karto's loop
//     (double per pose, bound check per entry) = the "before" of every optimisation.
//   * OccupancyGrid: the map of all loaded scans at 5 cm; SparseBox: the same and one scan
//     250 m away (a box of ~300 x 180 m that the beams barely cover), map image included.
// items_per_second is matches (or maps) per second; each iteration runs the same 30
// matches. CPU time is the figure to compare on a shared machine.
//
// Measured (intel slice, CPU ms per match, 2-core shared VM, so +-30 %):
//   loop coarse: reference 28.7 | integer sums, compiler-vectorised rows ~4 | register-blocked
//     SSE2 rows + far points clipped per row 1.3-1.7 | + branch and bound (4 x 16 blocks) 0.85-0.9
//   sequential (70 base scans, penalised, refined): reference 2.0-2.2 | integer search 1.6 |
//     + SSE2 smear 0.6-0.7 | + kernel-square clearing, filter fused into the grid 0.6-0.7
//   whole engine (slamtune run intel, slam_karto defaults): 15.9 s -> 14.1 s with the last step.
//   threads = 2 did not help on that machine (the second core was busy with other work).
//   grid build alone (GridBuild: ~6.5k hit cells, ~225k non-zero cells per build): 15.4 ->
//     14.2 ms per 30 builds with truncation instead of floor/ceil and hoisted loop bounds;
//     tried and dropped: prefetching kernel rows (no change) and aligned 2-chunk smears to
//     avoid store-forwarding stalls (16.4 ms, slower).
//   whole engine, medians of 3 interleaved runs on a noisy day: 24.2 s before, 19.5 s with
//     the grid build and lookup-table reuse, 16.7 s with the AVX2 row kernel as well.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/slam/matching/correlation_grid.h"
#include "slamtune/slam/matching/reference_scan_matcher.h"
#include "slamtune/slam/matching/scan_matcher.h"
#include "slamtune/slam/occupancy_grid.h"

namespace {

using slamtune::Pose2;
using slamtune::slam::LaserGeometry;
using slamtune::slam::LaserScan;
using slamtune::slam::Penalize;
using slamtune::slam::Refine;

std::vector<LaserScan> IntelScans() {
  const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/intel.clf.gz";
  if (!std::filesystem::exists(path)) return {};
  slamtune::io::LogReadOptions options;
  options.max_scans = 900;
  const slamtune::io::LaserLog log = slamtune::io::ReadCarmenLog(path, options);
  std::vector<LaserScan> scans;
  std::shared_ptr<const LaserGeometry> geometry;
  for (std::size_t i = 0; i < log.scans.size(); i += 3) {
    const auto& r = log.scans[i];
    if (!geometry) {
      auto g = std::make_shared<LaserGeometry>();
      g->min_angle = r.angle_min;
      g->angular_resolution = r.angle_increment;
      g->num_readings = static_cast<int>(r.ranges.size());
      g->max_range = r.max_range;
      g->range_threshold = std::min(12.0, r.max_range);
      geometry = g;
    }
    scans.emplace_back(geometry, std::make_shared<const std::vector<double>>(r.ranges), r.laser_pose, r.ipc_time);
  }
  return scans;
}

// A 12 m x 9 m room with a few obstacles, seen along a rounded rectangle.
std::vector<LaserScan> SyntheticScans() {
  struct Seg {
    double ax, ay, bx, by;
  };
  const std::vector<Seg> walls = {{0, 0, 12, 0}, {12, 0, 12, 9},   {12, 9, 0, 9},     {0, 9, 0, 0},
                                  {4, 3, 8, 3},  {8, 3, 8, 6},     {8, 6, 4, 6},      {4, 6, 4, 3},
                                  {1, 7, 2, 8},  {10, 1, 11, 1.5}, {6.5, 7.5, 7, 7.5}};
  auto g = std::make_shared<LaserGeometry>();
  g->min_angle = -slamtune::kPi / 2;
  g->angular_resolution = slamtune::kPi / 180;
  g->num_readings = 180;
  g->max_range = 81.83;
  std::vector<LaserScan> scans;
  for (int i = 0; i < 300; ++i) {
    const double t = 2 * slamtune::kPi * i / 150.0;
    const Pose2 pose{6 + 4.5 * std::cos(t), 4.5 + 3.2 * std::sin(t), t + slamtune::kPi / 2};
    auto ranges = std::make_shared<std::vector<double>>();
    for (int b = 0; b < 180; ++b) {
      const double a = pose.theta + g->min_angle + b * g->angular_resolution;
      const double dx = std::cos(a), dy = std::sin(a);
      double best = 81.83;
      for (const Seg& s : walls) {
        const double ex = s.bx - s.ax, ey = s.by - s.ay, wx = s.ax - pose.x, wy = s.ay - pose.y;
        const double den = dx * ey - dy * ex;
        if (std::fabs(den) < 1e-12) continue;
        const double tt = (wx * ey - wy * ex) / den, u = (wx * dy - wy * dx) / den;
        if (tt > 1e-9 && u >= 0 && u <= 1) best = std::min(best, tt);
      }
      ranges->push_back(best);
    }
    scans.emplace_back(g, ranges, pose, 0.0);
  }
  return scans;
}

const std::vector<LaserScan>& Scans() {
  static const std::vector<LaserScan> scans = [] {
    std::vector<LaserScan> s = IntelScans();
    return s.empty() ? SyntheticScans() : s;
  }();
  return scans;
}

slamtune::slam::ScanMatcherOptions SequentialOptions() { return {}; }

slamtune::slam::ScanMatcherOptions LoopOptions() {
  slamtune::slam::ScanMatcherOptions o;
  o.search_dimension = 8.0;
  o.search_resolution = 0.05;
  return o;
}

// Every iteration runs the same batch of matches: scan i against the `window` scans before
// it, for i = window, window + stride, ... (30 matches), so runs are comparable.
template <typename Matcher>
void RunMatches(benchmark::State& state, Matcher& matcher, std::size_t window, Penalize penalize, Refine refine) {
  const std::vector<LaserScan>& scans = Scans();
  const std::size_t batch = 30;
  const std::size_t stride = std::max<std::size_t>(1, (scans.size() - window) / batch);
  std::vector<std::vector<const LaserScan*>> bases;
  std::vector<const LaserScan*> queries;
  for (std::size_t i = window; i < scans.size() && queries.size() < batch; i += stride) {
    bases.emplace_back();
    for (std::size_t j = i - window; j < i; ++j) bases.back().push_back(&scans[j]);
    queries.push_back(&scans[i]);
  }
  double response_sum = 0.0;
  for (auto _ : state) {
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const auto result = matcher.Match(*queries[q], bases[q], penalize, refine);
      response_sum += result.response;
      benchmark::DoNotOptimize(result);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(queries.size()));
  state.counters["mean_response"] =
      response_sum / static_cast<double>(state.iterations() * static_cast<std::int64_t>(queries.size()));
  state.SetLabel(IntelScans().empty() ? "synthetic" : "intel");
}

void BM_Sequential(benchmark::State& state) {
  slamtune::slam::ScanMatcher matcher(SequentialOptions());
  RunMatches(state, matcher, 70, Penalize::kYes, Refine::kYes);
}
void BM_ReferenceSequential(benchmark::State& state) {
  slamtune::slam::ReferenceScanMatcher matcher(SequentialOptions());
  RunMatches(state, matcher, 70, Penalize::kYes, Refine::kYes);
}
// Arg 0: threads; arg 1: branch and bound on (1) or off (0, the exhaustive integer search).
void BM_LoopCoarse(benchmark::State& state) {
  auto o = LoopOptions();
  o.threads = static_cast<int>(state.range(0));
  o.branch_and_bound = state.range(1) != 0;
  slamtune::slam::ScanMatcher matcher(o);
  RunMatches(state, matcher, 12, Penalize::kNo, Refine::kNo);
}
// The near-chain / loop-fine use of the sequential matcher: no penalty, refined.
void BM_SequentialUnpenalised(benchmark::State& state) {
  slamtune::slam::ScanMatcher matcher(SequentialOptions());
  RunMatches(state, matcher, 20, Penalize::kNo, Refine::kYes);
}
// A front-end search's wider sequential windows, penalised and refined as slam_karto's
// sequential match, heading range 0.7 rad (arg: window in cm). A penalised pass is exhaustive:
// a branch and bound on penalised responses, pooling the 6 MB grid per match as the loop
// matcher's does, measured 1.7x slower at 1.6 m and slower at every window here.
void BM_SequentialWide(benchmark::State& state) {
  auto o = SequentialOptions();
  o.search_dimension = static_cast<double>(state.range(0)) / 100.0;
  o.coarse_angle_offset = 0.7;
  slamtune::slam::ScanMatcher matcher(o);
  RunMatches(state, matcher, 70, Penalize::kYes, Refine::kYes);
}
void BM_ReferenceLoopCoarse(benchmark::State& state) {
  slamtune::slam::ReferenceScanMatcher matcher(LoopOptions());
  RunMatches(state, matcher, 12, Penalize::kNo, Refine::kNo);
}
// The correlation-grid build alone (clear, back-face filter, insert, smear) of the
// sequential matcher's grid from 70 base scans, for the same 30 queries as BM_Sequential.
void BM_GridBuild(benchmark::State& state) {
  const std::vector<LaserScan>& scans = Scans();
  const auto o = SequentialOptions();
  slamtune::slam::CorrelationGrid grid(o.search_dimension, o.search_resolution, o.smear_deviation,
                                       scans.front().geometry().range_threshold);
  const std::size_t window = 70, batch = 30;
  const std::size_t stride = std::max<std::size_t>(1, (scans.size() - window) / batch);
  std::vector<std::vector<const LaserScan*>> bases;
  std::vector<Eigen::Vector2d> centres;
  for (std::size_t i = window; i < scans.size() && centres.size() < batch; i += stride) {
    bases.emplace_back();
    for (std::size_t j = i - window; j < i; ++j) bases.back().push_back(&scans[j]);
    const Pose2& p = scans[i].corrected_pose();
    centres.emplace_back(p.x, p.y);
  }
  const double half = 0.5 * (grid.geometry().roi_side - 1) * grid.resolution();
  for (auto _ : state) {
    for (std::size_t q = 0; q < centres.size(); ++q) {
      grid.SetRoiOrigin(centres[q] - Eigen::Vector2d(half, half));
      grid.AddScans(bases[q], centres[q]);
      benchmark::DoNotOptimize(grid.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(centres.size()));
  // What one build writes, averaged over the queries (outside the timed loop).
  std::int64_t hits = 0, nonzero = 0;
  for (std::size_t q = 0; q < centres.size(); ++q) {
    grid.SetRoiOrigin(centres[q] - Eigen::Vector2d(half, half));
    grid.AddScans(bases[q], centres[q]);
    for (std::int32_t i = 0; i < grid.data_size(); ++i) {
      hits += grid.data()[i] == slamtune::slam::kCorrelationOccupied;
      nonzero += grid.data()[i] != 0;
    }
  }
  state.counters["hit_cells"] = static_cast<double>(hits) / static_cast<double>(centres.size());
  state.counters["nonzero_cells"] = static_cast<double>(nonzero) / static_cast<double>(centres.size());
}
void BM_OccupancyGrid(benchmark::State& state) {
  const std::vector<LaserScan>& scans = Scans();
  for (auto _ : state) {
    const auto grid = slamtune::slam::OccupancyGrid::FromScans(std::span<const LaserScan>(scans), {});
    benchmark::DoNotOptimize(grid.summary());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["scans"] = static_cast<double>(scans.size());
}

// The same scans with a copy of the last one 250 m away: a box as large as a long building
// (or a broken trajectory) whose cells no beam ever reaches, where the map's cost should be
// the cells the beams cross, not its area.
void BM_OccupancyGridSparseBox(benchmark::State& state) {
  std::vector<LaserScan> scans = Scans();
  LaserScan far = scans.back();
  const Pose2 pose = far.corrected_pose();
  far.SetCorrectedPose({pose.x + 250.0, pose.y + 150.0, pose.theta});
  scans.push_back(far);
  for (auto _ : state) {
    const auto grid = slamtune::slam::OccupancyGrid::FromScans(std::span<const LaserScan>(scans), {});
    benchmark::DoNotOptimize(grid.ToMapImage());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["scans"] = static_cast<double>(scans.size());
}

BENCHMARK(BM_Sequential)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceSequential)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SequentialUnpenalised)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoopCoarse)
    ->Args({1, 1})
    ->Args({1, 0})
    ->Args({2, 0})
    ->ArgNames({"threads", "bnb"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SequentialWide)
    ->Arg(30)
    ->Arg(60)
    ->Arg(90)
    ->Arg(120)
    ->Arg(160)
    ->ArgName("window_cm")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceLoopCoarse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridBuild)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OccupancyGrid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OccupancyGridSparseBox)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
