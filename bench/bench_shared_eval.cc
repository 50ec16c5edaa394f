// Shared scan matches (slam/sharing/match_cache.h) on an optimiser-sized batch: N parameter sets drawn
// as `slamtune optimize` draws its initial population (r uniform in [2, 6] m, integer g in
// [6, 20], pagmo's generator from --seed) are evaluated (a) each on its own, without the
// cache, and (b) as one batch sharing the cache, both on --jobs threads. Checks that every
// result (objectives, loop closures, trajectory bits, map pixels) is identical, then prints
// wall times, the speed-up, the cache counters and peak RSS (/proc/self/status VmHWM).
//
// With --whole it measures instead the whole optimisation (`slamtune optimize`'s path: NSGA-III,
// run database, every sharing cache) at the paper's budget (66 x 60, or --population and
// --generations), against population x (generations + 1) x the wall time of one standalone run
// of slam_karto's defaults (r 4, g 10, p 0.7, q 0.4) in the same invocation (the median of
// three such runs: two before the optimisation, one after), and reports the peak RSS.
//
//   bench_shared_eval [LOG] [--quick] [--sets N] [--jobs J] [--seed S]
//   bench_shared_eval [LOG] --whole [--population N] [--generations G] [--jobs J] [--seed S]
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <pagmo/problem.hpp>
#include <pagmo/rng.hpp>
#include <pagmo/utils/generic.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/optim/optimizer.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/optim/tuning_problem.h"
#include "slamtune/sim/simulation.h"

namespace {

using slamtune::optim::Assignment;

// FNV-1a over 64-bit words: a digest of everything a run produced, bit-exact.
struct Digest {
  std::uint64_t h = 1469598103934665603ULL;
  void Add(std::uint64_t w) {
    for (int k = 0; k < 8; ++k) {
      h ^= (w >> (8 * k)) & 0xff;
      h *= 1099511628211ULL;
    }
  }
  void Add(double v) { Add(std::bit_cast<std::uint64_t>(v)); }
};

std::uint64_t DigestOf(const slamtune::optim::EvaluationRecord& r, const slamtune::optim::SlamRun& run) {
  Digest d;
  for (slamtune::optim::Objective o : slamtune::optim::AllObjectives()) {
    d.Add(r.status == slamtune::optim::RunStatus::kOk ? slamtune::optim::ValueOf(r, o)
                                                      : slamtune::optim::InfoOf(o).failure_score);
  }
  d.Add(r.occupied_ratio_known);
  d.Add(static_cast<std::uint64_t>(r.nodes));
  for (const auto& l : run.summary.loop_closures) {
    d.Add(static_cast<std::uint64_t>(l.log_index));
    d.Add(static_cast<std::uint64_t>(l.chain_first));
    d.Add(l.coarse_response);
    d.Add(l.fine_response);
  }
  for (const auto& p : run.trajectory) {
    d.Add(p.pose.x);
    d.Add(p.pose.y);
    d.Add(p.pose.theta);
  }
  d.Add(static_cast<std::uint64_t>(run.map.width));
  d.Add(static_cast<std::uint64_t>(run.map.height));
  for (std::uint8_t px : run.map.pixels) d.Add(static_cast<std::uint64_t>(px));
  return d.h;
}

struct BatchResult {
  std::vector<std::uint64_t> digests;
  std::vector<int> loops;
  double wall_s = 0.0;
};

// Evaluates `sets` on `jobs` threads (each thread takes the next set), as BatchEvaluator does.
BatchResult Evaluate(const slamtune::optim::SlamEvaluationContext& context, const std::vector<Assignment>& sets,
                     int jobs) {
  BatchResult out;
  out.digests.resize(sets.size());
  out.loops.resize(sets.size());
  std::atomic<std::size_t> next{0};
  const auto start = std::chrono::steady_clock::now();
  auto work = [&] {
    for (std::size_t i = next++; i < sets.size(); i = next++) {
      slamtune::optim::SlamRun run;
      const auto record = slamtune::optim::EvaluateSlam(context, sets[i], &run);
      out.digests[i] = DigestOf(record, run);
      out.loops[i] = record.loop_closures;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < jobs; ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string ProcStatus(const std::string& field) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind(field + ":", 0) == 0) {
      const auto p = line.find_first_not_of(" \t", field.size() + 1);
      return p == std::string::npos ? "" : line.substr(p);
    }
  }
  return "?";
}

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// --whole: one default run, then the optimisation, in this invocation.
int RunWhole(const slamtune::optim::SlamEvaluationContext& plain, const std::string& label, std::size_t population,
             unsigned generations, int jobs, unsigned seed) {
  using namespace slamtune;
  optim::OptimizeSettings settings;
  settings.population = population;
  settings.divisions = 10;  // the paper's 66 reference points, whatever the population
  settings.generations = generations;
  settings.seed = seed;
  for (const auto& d : settings.space.dimensions) {
    settings.default_assignment[d.name] = slam::GetNumeric(slam::MapperParams{}, d.name);
  }
  for (const auto& [name, value] : settings.space.fixed) settings.default_assignment[name] = value;
  settings.source.log_label = label;
  settings.Validate();

  std::printf("%s: %zu scans; whole optimisation, population %zu, %u generations, %d jobs, seed %u\n", label.c_str(),
              plain.log->scans.size(), population, generations, jobs, seed);
  std::fflush(stdout);
  // The yardstick is the median of three standalone default runs, two before the optimisation
  // and one after it, so that neither one slow sample nor a drift of the machine's speed during
  // a long optimisation decides the ratio.
  auto time_default_run = [&] {
    const auto t0 = std::chrono::steady_clock::now();
    const optim::EvaluationRecord one = optim::EvaluateSlam(plain, settings.default_assignment);
    const double s = Seconds(t0);
    std::printf("one default run (no sharing, 1 thread): %.2f s, %d loop closures\n", s, one.loop_closures);
    std::fflush(stdout);
    return s;
  };
  std::vector<double> default_runs = {time_default_run(), time_default_run()};
  auto start = std::chrono::steady_clock::now();

  optim::SlamEvaluationContext shared = plain;
  optim::ShareWork(shared, 512);  // what `slamtune optimize` shares at its default --share-mb
  const auto db = std::filesystem::temp_directory_path() / fmt::format("bench_whole_{}.sqlite", ::getpid());
  std::filesystem::remove(db);
  optim::OptimizeResult result;
  {
    optim::EvaluationStore store(db.string());
    optim::BatchEvaluator evaluator([&shared](const Assignment& a) { return optim::EvaluateSlam(shared, a); }, &store,
                                    jobs);
    optim::OptimizeHooks hooks;
    hooks.progress = [](const std::string& line, bool force) {
      if (force) {
        std::printf("  %s\n", line.c_str());
        std::fflush(stdout);
      }
    };
    start = std::chrono::steady_clock::now();
    result = optim::RunOptimization(settings, evaluator, store, optim::OptimizationStart::kNew, hooks);
  }
  const double wall = Seconds(start);
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix);
  default_runs.push_back(time_default_run());
  std::sort(default_runs.begin(), default_runs.end());
  const double one_s = default_runs[1];
  std::printf("default run: median %.2f s of %.2f, %.2f, %.2f (two before the optimisation, one after)\n", one_s,
              default_runs[0], default_runs[1], default_runs[2]);
  const double requested = static_cast<double>(population * (generations + 1));
  std::printf("whole optimisation: %.1f s wall, %zu SLAM runs done, %zu requests served without a run\n", wall,
              result.evaluation_count, result.cache_hits);
  // The yardstick is the paper's 66 x 60 = 3960 runs; the optimiser evaluates the initial
  // population too (66 x 61 requests), so both are printed.
  const double paper = static_cast<double>(population * generations);
  std::printf("one after another: %.0f requests x %.2f s = %.1f s; speed-up %.1fx (per SLAM run done: %.1fx)\n",
              requested, one_s, requested * one_s, requested * one_s / wall,
              static_cast<double>(result.evaluation_count) * one_s / wall);
  std::printf("against population x generations = %.0f runs x %.2f s = %.1f s: %.1fx\n", paper, one_s, paper * one_s,
              paper * one_s / wall);
  std::printf("%s\n", optim::SharedWorkReport(shared).c_str());
  std::printf("peak RSS %s\n", ProcStatus("VmHWM").c_str());
  const auto* best = result.Find("recommended");
  if (best != nullptr) {
    std::printf("recommended: r %.4g g %.0f, %d loop closures\n",
                best->record.params.at("loop_search_maximum_distance"),
                best->record.params.at("loop_match_minimum_chain_size"), best->record.loop_closures);
  }
  return 0;
}

int Run(int argc, char** argv) {
  CLI::App app{"Wall time of a batch of SLAM evaluations with and without shared scan matches"};
  std::string log_path;
  bool quick = false;
  int sets = 66;
  int jobs = 2;
  unsigned seed = 1;
  bool whole = false;
  std::size_t population = 66;
  unsigned generations = 60;
  app.add_option("LOG", log_path, "CARMEN log; none: the built-in office world");
  app.add_flag("--whole", whole, "time the whole optimisation against one default run x its budget");
  app.add_option("--population", population, "--whole: population (8 with --quick)")->capture_default_str();
  app.add_option("--generations", generations, "--whole: generations (2 with --quick)")->capture_default_str();
  app.add_flag("--quick", quick, "8 sets at most and the first 500 scans of the log");
  app.add_option("--sets", sets, "parameter sets (the optimiser's population)")->capture_default_str();
  app.add_option("--jobs,-j", jobs, "parallel SLAM runs in both modes")->capture_default_str();
  app.add_option("--seed", seed, "seed of the drawn sets")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (sets < 1) throw slamtune::InputError(fmt::format("--sets = {} is out of range: must be >= 1", sets));
  if (jobs < 1) throw slamtune::InputError(fmt::format("--jobs = {} is out of range: must be >= 1", jobs));
  if (quick) sets = std::min(sets, 8);
  if (quick && whole) {
    population = std::min<std::size_t>(population, 8);
    generations = std::min(generations, 2u);
  }

  // The inputs as `slamtune optimize` loads them without options (cli/tuning_inputs.cc): the
  // default parameters; no log: the office world, seed 1, with its true-trajectory relations.
  auto log = std::make_shared<slamtune::io::LaserLog>();
  std::vector<slamtune::io::Relation> relations;
  std::string label = log_path;
  if (log_path.empty()) {
    slamtune::sim::SimulationOptions sim_options;
    sim_options.world = "office";
    slamtune::sim::Simulation simulation = slamtune::sim::Simulate(sim_options);
    *log = std::move(simulation.log);
    relations = std::move(simulation.relations);
    label = "built-in world office (seed 1)";
  } else {
    *log = slamtune::io::ReadCarmenLog(log_path);
  }
  if (quick && log->scans.size() > 500) {
    log->scans.resize(500);
    relations.clear();  // they refer to the whole log
  }

  if (whole) {
    slamtune::optim::SlamEvaluationContext plain;
    plain.log = log;
    plain.relations = relations;
    for (const auto& [name, value] : slamtune::optim::SearchSpace::PaperDefault().fixed) {
      slamtune::slam::SetNumeric(plain.base, name, value);
    }
    return RunWhole(plain, label, population, generations, jobs, seed);
  }

  // The optimiser's initial population (optimizer.cc InitialPopulation).
  const slamtune::optim::SearchSpace space = slamtune::optim::SearchSpace::PaperDefault();
  // The problem is only asked for its bounds here; its evaluator is never called.
  auto unused = std::make_shared<slamtune::optim::BatchEvaluator>(
      [](const Assignment&) -> slamtune::optim::EvaluationRecord { throw std::logic_error("not used"); }, nullptr, 1);
  const pagmo::problem problem{slamtune::optim::TuningProblem(space, slamtune::optim::ObjectiveSet(), unused)};
  pagmo::detail::random_engine_type rng(seed);
  std::vector<Assignment> batch;
  for (int i = 0; i < sets; ++i) batch.push_back(space.Assign(pagmo::random_decision_vector(problem, rng)));

  slamtune::optim::SlamEvaluationContext plain;
  plain.log = log;
  plain.relations = relations;
  for (const auto& [name, value] : space.fixed) slamtune::slam::SetNumeric(plain.base, name, value);
  slamtune::optim::SlamEvaluationContext shared = plain;
  shared.shared_work.match_cache = std::make_shared<slamtune::slam::MatchCache>();
  shared.shared_work.solve_cache = std::make_shared<slamtune::slam::SolveCache>();
  shared.shared_work.barycenter_cache = std::make_shared<slamtune::slam::BarycenterCache>();

  std::printf("%s: %zu scans, %d sets, %d jobs, seed %u\n", label.c_str(), log->scans.size(), sets, jobs, seed);
  std::fflush(stdout);
  const BatchResult a = Evaluate(plain, batch, jobs);
  const std::string hwm_a = ProcStatus("VmHWM");
  std::printf("(a) without the cache: %.2f s (peak RSS so far %s)\n", a.wall_s, hwm_a.c_str());
  std::fflush(stdout);
  const BatchResult b = Evaluate(shared, batch, jobs);
  std::printf("(b) shared cache:      %.2f s (peak RSS so far %s)\n", b.wall_s, ProcStatus("VmHWM").c_str());
  int differing = 0;
  int loops_min = 1 << 30, loops_max = 0;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    if (a.digests[i] != b.digests[i]) ++differing;
    loops_min = std::min(loops_min, a.loops[i]);
    loops_max = std::max(loops_max, a.loops[i]);
  }
  std::printf("speed-up (a)/(b): %.2fx; loop closures per set %d..%d\n", a.wall_s / b.wall_s, loops_min, loops_max);
  std::printf("%s\n%s\n%s\n", shared.shared_work.match_cache->counters().ToString().c_str(),
              shared.shared_work.solve_cache->counters().ToString().c_str(),
              shared.shared_work.barycenter_cache->counters().ToString().c_str());
  std::printf("results identical: %s (%d of %d sets differ)\n", differing == 0 ? "yes" : "NO", differing, sets);
  return differing == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const slamtune::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
