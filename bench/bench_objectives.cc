// Do the map objectives rank SLAM runs the way the true error does? N parameter sets are drawn
// uniformly from a search space (the front-end space by default, so that both regimes occur:
// runs whose front end holds and runs whose map breaks), each is run on a log with ground-truth
// relations or on a built-in world (whose true trajectory gives the relations), and the bench
// prints, for every map figure an objective can use, Spearman's rho against the mean
// translational error (positive: lower figure, lower error), then for each objective set the
// runs it would put forward: its non-dominated front and that front's knee, with their errors
// and how many of them are broken (error above max(2 x the best run's, best + 5 cm)).
//
//   bench_objectives LOG --relations FILE [--space front-end|loop] [--runs N] [--jobs J] [--seed S]
//   bench_objectives --world NAME [...]            (a built-in world, seed 1)
//   ... [--csv FILE]                               every run: parameters, figures, error
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/relations.h"
#include "slamtune/optim/candidate_selection.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/report/rank_correlation.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/params/mapper_params.h"

namespace {

using slamtune::optim::EvaluationRecord;
using slamtune::optim::Objective;
using slamtune::optim::ObjectiveSet;
using slamtune::optim::ObjectiveSetKind;

struct Figure {
  std::string name;
  double (*get)(const EvaluationRecord&);
};

// The objectives, then second figures worth knowing about.
std::vector<Figure> Figures() {
  return {
      {"u_h (unbacked hits)", [](const EvaluationRecord& r) { return ValueOf(r, Objective("unbacked_hits")); }},
      {"eta (paper)", [](const EvaluationRecord& r) { return r.occupied_ratio; }},
      {"n_c (corner pixels)", [](const EvaluationRecord& r) { return r.corner_pixels; }},
      {"n_e (enclosed areas)", [](const EvaluationRecord& r) { return r.enclosed_areas; }},
      {"occupied / known", [](const EvaluationRecord& r) { return r.occupied_ratio_known; }},
      {"occupied cells", [](const EvaluationRecord& r) { return r.occupied_cells; }},
      {"corner clusters", [](const EvaluationRecord& r) { return r.corners; }},
      {"hits in free / hits",
       [](const EvaluationRecord& r) { return r.hits > 0 ? r.hits_in_free_cells / r.hits : 1.0; }},
      {"n_w (drawn wall cells)", [](const EvaluationRecord& r) { return r.drawn_wall_cells; }},
  };
}

// N random assignments of `space`: each dimension uniform in its range (integers rounded).
std::vector<slamtune::optim::Assignment> Draw(const slamtune::optim::SearchSpace& space, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<slamtune::optim::Assignment> out;
  for (int i = 0; i < n; ++i) {
    std::vector<double> x;
    for (const auto& d : space.dimensions) {
      double v = std::uniform_real_distribution<double>(d.lower, d.upper)(rng);
      if (d.integer) v = std::clamp(std::round(v), d.lower, d.upper);
      x.push_back(v);
    }
    out.push_back(space.Assign(x));
  }
  return out;
}

std::vector<EvaluationRecord> EvaluateAll(const slamtune::optim::SlamEvaluationContext& context,
                                          const std::vector<slamtune::optim::Assignment>& sets, int jobs) {
  std::vector<EvaluationRecord> out(sets.size());
  std::atomic<std::size_t> next{0}, done{0};
  auto work = [&] {
    for (std::size_t i = next++; i < sets.size(); i = next++) {
      try {
        out[i] = slamtune::optim::EvaluateSlam(context, sets[i]);
      } catch (const std::exception& e) {
        out[i] = EvaluationRecord::Failed("", sets[i], e.what());
      }
      out[i].key = slamtune::optim::SearchSpace::Key(sets[i]);
      out[i].params = sets[i];
      const std::size_t d = ++done;
      if (d % 10 == 0 || d == sets.size()) std::fprintf(stderr, "  %zu/%zu runs\n", d, sets.size());
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < jobs; ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  return out;
}

void WriteCsv(const std::string& path, const std::vector<EvaluationRecord>& runs) {
  std::ofstream f(path);
  if (!f) throw slamtune::InputError(path, 0, "cannot write the CSV file");
  const auto figures = Figures();
  f << "run";
  for (const auto& [name, value] : runs.front().params) f << "," << name;
  for (const auto& fig : figures) f << ",\"" << fig.name << "\"";
  f << ",loop_closures,trans_mean_m\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    f << i;
    for (const auto& [name, value] : runs[i].params) f << "," << fmt::format("{:.6g}", value);
    for (const auto& fig : figures) f << "," << fmt::format("{:.6g}", fig.get(runs[i]));
    f << "," << runs[i].loop_closures << "," << fmt::format("{:.6g}", runs[i].trans_mean_m) << "\n";
  }
}

int Run(int argc, char** argv) {
  CLI::App app{"Spearman rho of each map figure against the true error over random parameter sets"};
  std::string log_path, relations_path, world, space_name = "front-end", csv;
  int runs = 60, jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  unsigned seed = 1;
  app.add_option("LOG", log_path, "log or recording (CARMEN, ROS 2, ROS 1)");
  app.add_option("--relations", relations_path, "ground-truth relations of LOG");
  app.add_option("--world", world, "a built-in world instead of LOG (its true trajectory gives the relations)");
  app.add_option("--space", space_name, "front-end (sequential matching, node spacing, r, g, p, q) or loop (r, g)")
      ->capture_default_str();
  app.add_option("--runs", runs, "parameter sets drawn")->capture_default_str();
  app.add_option("--jobs,-j", jobs, "parallel SLAM runs")->capture_default_str();
  app.add_option("--seed", seed, "seed of the draw")->capture_default_str();
  app.add_option("--csv", csv, "write every run's parameters, figures and error here");
  CLI11_PARSE(app, argc, argv);
  if (runs < 5) throw slamtune::InputError(fmt::format("--runs = {} is out of range: must be >= 5", runs));
  if (jobs < 1) throw slamtune::InputError(fmt::format("--jobs = {} is out of range: must be >= 1", jobs));
  if (world.empty() == log_path.empty()) throw slamtune::InputError("give either LOG --relations FILE or --world NAME");

  slamtune::optim::SlamEvaluationContext context;
  auto log = std::make_shared<slamtune::io::LaserLog>();
  std::string label;
  if (!world.empty()) {
    slamtune::sim::SimulationOptions sim_options;
    sim_options.world = world;
    slamtune::sim::Simulation simulation = slamtune::sim::Simulate(sim_options);
    *log = std::move(simulation.log);
    context.relations = std::move(simulation.relations);
    label = "world " + world;
  } else {
    if (relations_path.empty()) throw slamtune::InputError("--relations FILE is required with LOG");
    *log = slamtune::io::ReadLaserLog(log_path);
    context.relations = slamtune::io::ReadRelations(relations_path);
    label = log_path;
  }
  context.log = log;
  slamtune::optim::DrawWall(context, slamtune::optim::WallDrawing::kDraw);
  std::fprintf(stderr, "drawn wall: %zu of %zu scans drawn along each path\n",
               context.trajectory_map->scan_indices().size(), log->scans.size());
  slamtune::optim::ShareWork(context, 512);
  const slamtune::optim::SearchSpace space =
      space_name == "loop" ? slamtune::optim::SearchSpace::AroundBase(context.base.loop_search_maximum_distance,
                                                                      context.base.loop_match_minimum_chain_size)
      : space_name == "front-end"
          ? slamtune::optim::SearchSpace::FrontEnd(context.base)
          : throw slamtune::InputError("--space must be front-end or loop, got '" + space_name + "'");

  std::printf("%s: %zu scans, %d parameter sets from the %s space, seed %u, %d jobs\n", label.c_str(),
              log->scans.size(), runs, space_name.c_str(), seed, jobs);
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  std::vector<EvaluationRecord> all = EvaluateAll(context, Draw(space, runs, seed), jobs);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<EvaluationRecord> ok;
  for (const auto& r : all)
    if (r.status == slamtune::optim::RunStatus::kOk && r.has_gt) ok.push_back(r);
  if (ok.size() < 5) throw slamtune::InputError(fmt::format("only {} runs succeeded with ground truth", ok.size()));
  if (!csv.empty()) WriteCsv(csv, ok);

  std::vector<double> error;
  for (const auto& r : ok) error.push_back(r.trans_mean_m);
  std::vector<double> sorted = error;
  std::sort(sorted.begin(), sorted.end());
  const double best = sorted.front();
  const double broken_above = std::max(2.0 * best, best + 0.05);
  auto broken = [&](const EvaluationRecord& r) { return r.trans_mean_m > broken_above; };
  const auto n_broken = std::count_if(ok.begin(), ok.end(), broken);
  std::printf("%zu of %zu runs ok, %.0f s; error min %.4f median %.4f max %.4f m; broken (> %.4f m): %ld\n", ok.size(),
              all.size(), wall, best, sorted[sorted.size() / 2], sorted.back(), broken_above, n_broken);

  std::printf("\n| figure | Spearman rho vs error |\n|---|---|\n");
  for (const auto& fig : Figures()) {
    std::vector<double> v;
    for (const auto& r : ok) v.push_back(fig.get(r));
    const auto rho = slamtune::report::SpearmanCorrelation(v, error);
    std::printf("| %s | %s |\n", fig.name.c_str(), rho.defined ? fmt::format("{:+.3f}", rho.rho).c_str() : "undefined");
  }

  std::printf(
      "\n| objectives | front size | broken in front | front error min..max m | knee error m | knee broken |\n"
      "|---|---|---|---|---|---|\n");
  for (ObjectiveSetKind kind : {ObjectiveSetKind::kDrawn, ObjectiveSetKind::kOccupied, ObjectiveSetKind::kConsistency,
                                ObjectiveSetKind::kPaper}) {
    const ObjectiveSet set(kind);
    const auto front = slamtune::optim::NonDominated(ok, set);
    double lo = 1e300, hi = 0;
    int front_broken = 0;
    for (std::size_t i : front) {
      lo = std::min(lo, ok[i].trans_mean_m);
      hi = std::max(hi, ok[i].trans_mean_m);
      front_broken += broken(ok[i]) ? 1 : 0;
    }
    const EvaluationRecord& knee = ok[slamtune::optim::Knee(ok, set)];
    std::printf("| %s | %zu | %d | %.4f..%.4f | %.4f | %s |\n", set.name(), front.size(), front_broken, lo, hi,
                knee.trans_mean_m, broken(knee) ? "yes" : "no");
  }
  return 0;
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
