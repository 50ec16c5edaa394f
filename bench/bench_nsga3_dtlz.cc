// NSGA-III on DTLZ1-DTLZ4 (M = 3) against pagmo's NSGA-II and MOEA/D, as in Deb & Jain
// 2014, §VI-A / Table III: n = M + k - 1 with k = 5 (DTLZ1) or 10 (DTLZ2-4), D = 12 (91
// reference points), N = 92, generations 400 / 250 / 1000 / 600. For each problem and
// algorithm prints best / median / worst IGD over the seeds, measured against the 91 targeted
// points where the reference directions meet the true front (DTLZ1: sum f = 0.5; DTLZ2-4:
// |f| = 1), and the hypervolume w.r.t. 1.1 x the nadir of the true front.
//
//   bench_nsga3_dtlz [--problems dtlz1,dtlz2] [--seeds 20] [--generations-scale 0.1] [--json]
//
// Same-invocation baselines: pagmo::nsga2 with NSGA-III's operators (eta_c = 30, p_m = 1/n,
// eta_m = 20; crossover probability just below 1 because pagmo requires cr < 1) and N = 92;
// pagmo::moead with its defaults (Tchebycheff, DE operator, 20 neighbours) and the same 91
// "grid" weight vectors, so N = 91. Each algorithm evolves the same seeded initial population
// (its first 91 members for MOEA/D). IGD and hypervolume use the non-dominated members of
// the final population.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problems/dtlz.hpp>
#include <pagmo/utils/hypervolume.hpp>
#include <pagmo/utils/multi_objective.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/nsga3/igd.h"
#include "slamtune/nsga3/nsga3.h"
#include "slamtune/nsga3/reference_points.h"

namespace {

using slamtune::nsga3::ReferencePoints;
using Points = std::vector<std::vector<double>>;

constexpr std::size_t kObjectives = 3;
constexpr std::size_t kDivisions = 12;  // H = 91
constexpr std::size_t kPopulation = 92;

struct DtlzCase {
  std::string name;
  unsigned id;
  std::size_t k;         // distance variables
  unsigned generations;  // Table III of the paper
  bool linear_front;     // DTLZ1: sum f = 0.5, else |f| = 1
};

const std::vector<DtlzCase> kCases = {
    {"dtlz1", 1, 5, 400, true},
    {"dtlz2", 2, 10, 250, false},
    {"dtlz3", 3, 10, 1000, false},
    {"dtlz4", 4, 10, 600, false},
};

struct RunResult {
  double igd = 0.0;
  double hypervolume = 0.0;
  double seconds = 0.0;
};

Points NonDominated(const Points& f) {
  Points front;
  const auto sorted = pagmo::fast_non_dominated_sorting(f);
  for (auto index : std::get<0>(sorted).front()) front.push_back(f[index]);
  return front;
}

double Hypervolume(const Points& front, const std::vector<double>& reference) {
  Points inside;  // points that strictly dominate the reference point
  for (const auto& p : front) {
    bool dominates = true;
    for (std::size_t i = 0; i < p.size(); ++i) dominates = dominates && p[i] < reference[i];
    if (dominates) inside.push_back(p);
  }
  if (inside.empty()) return 0.0;
  return pagmo::hypervolume(inside).compute(reference);
}

RunResult Measure(const Points& final_f, const Points& targets, const std::vector<double>& hv_reference,
                  double seconds) {
  const Points front = NonDominated(final_f);
  return {slamtune::nsga3::InvertedGenerationalDistance(targets, front), Hypervolume(front, hv_reference), seconds};
}

template <typename Evolve>
RunResult Timed(const Evolve& evolve, const Points& targets, const std::vector<double>& hv_reference) {
  const auto start = std::chrono::steady_clock::now();
  const pagmo::population pop = evolve();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Measure(pop.get_f(), targets, hv_reference, seconds);
}

struct Stats {
  double best, median, worst;
};

// best / median / worst; `lower_is_better` orders IGD, else hypervolume.
Stats Summarize(std::vector<double> values, bool lower_is_better) {
  std::sort(values.begin(), values.end());
  if (!lower_is_better) std::reverse(values.begin(), values.end());
  const std::size_t n = values.size();
  const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return {values.front(), median, values.back()};
}

std::vector<std::string> Split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

int Run(const std::vector<std::string>& problems, unsigned seeds, double generations_scale, bool json) {
  std::vector<DtlzCase> cases;
  for (const std::string& name : problems) {
    const auto it = std::find_if(kCases.begin(), kCases.end(), [&](const DtlzCase& c) { return c.name == name; });
    if (it == kCases.end())
      throw slamtune::InputError("--problems: unknown problem '" + name + "', expected dtlz1..dtlz4");
    cases.push_back(*it);
  }
  const ReferencePoints directions = slamtune::nsga3::DasDennisPoints(kObjectives, kDivisions);
  nlohmann::json out = nlohmann::json::array();
  if (!json) {
    std::printf("%-6s %-9s %5s | %-33s | %-33s | %s\n", "prob", "algo", "gens", "IGD best / median / worst",
                "HV best / median / worst", "s/run");
  }
  for (const DtlzCase& c : cases) {
    const unsigned generations =
        std::max(1u, static_cast<unsigned>(std::lround(generations_scale * static_cast<double>(c.generations))));
    const std::size_t n = kObjectives + c.k - 1;
    const pagmo::problem prob(pagmo::dtlz(c.id, n, kObjectives));
    const Points targets = c.linear_front ? slamtune::nsga3::TargetsOnSimplex(directions, 0.5)
                                          : slamtune::nsga3::TargetsOnUnitSphere(directions);
    const std::vector<double> hv_reference(kObjectives, c.linear_front ? 0.55 : 1.1);

    std::map<std::string, std::vector<RunResult>> results;
    for (unsigned seed = 1; seed <= seeds; ++seed) {
      const pagmo::population start(prob, kPopulation, seed);
      pagmo::population start91(prob);
      for (std::size_t k = 0; k < 91; ++k) start91.push_back(start.get_x()[k], start.get_f()[k]);

      slamtune::nsga3::Nsga3Options options;
      options.generations = generations;
      options.divisions = kDivisions;
      results["NSGA-III"].push_back(
          Timed([&] { return slamtune::nsga3::Nsga3(options, seed).evolve(start); }, targets, hv_reference));
      const pagmo::nsga2 nsga2(generations, std::nextafter(1.0, 0.0), 30.0, 1.0 / static_cast<double>(n), 20.0, seed);
      results["NSGA-II"].push_back(Timed([&] { return nsga2.evolve(start); }, targets, hv_reference));
      const pagmo::moead moead(generations, "grid", "tchebycheff", 20u, 1.0, 0.5, 20.0, 0.9, 2u, true, seed);
      results["MOEA/D"].push_back(Timed([&] { return moead.evolve(start91); }, targets, hv_reference));
    }
    for (const std::string algo : {"NSGA-III", "NSGA-II", "MOEA/D"}) {
      std::vector<double> igd, hv;
      double seconds = 0.0;
      for (const RunResult& r : results[algo]) {
        igd.push_back(r.igd);
        hv.push_back(r.hypervolume);
        seconds += r.seconds;
      }
      const Stats si = Summarize(igd, true), sh = Summarize(hv, false);
      const double per_run = seconds / static_cast<double>(seeds);
      if (json) {
        out.push_back({{"problem", c.name},
                       {"algorithm", algo},
                       {"generations", generations},
                       {"seeds", seeds},
                       {"igd", {{"best", si.best}, {"median", si.median}, {"worst", si.worst}, {"all", igd}}},
                       {"hypervolume", {{"best", sh.best}, {"median", sh.median}, {"worst", sh.worst}, {"all", hv}}},
                       {"seconds_per_run", per_run}});
      } else {
        std::printf("%-6s %-9s %5u | %.3e / %.3e / %.3e | %.4e / %.4e / %.4e | %.2f\n", c.name.c_str(), algo.c_str(),
                    generations, si.best, si.median, si.worst, sh.best, sh.median, sh.worst, per_run);
        std::fflush(stdout);
      }
    }
  }
  if (json) std::printf("%s\n", out.dump(2).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"NSGA-III vs NSGA-II vs MOEA/D on DTLZ1-4 (M = 3), IGD and hypervolume"};
  std::string problems = "dtlz1,dtlz2,dtlz3,dtlz4";
  unsigned seeds = 20;
  double generations_scale = 1.0;
  bool json = false;
  app.add_option("--problems", problems, "comma-separated subset of dtlz1,dtlz2,dtlz3,dtlz4");
  app.add_option("--seeds", seeds, "independent runs per problem and algorithm (seeds 1..N)")
      ->check(CLI::PositiveNumber);
  app.add_option("--generations-scale", generations_scale, "multiply the paper's generation counts (quick runs)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--json", json, "print the results as JSON instead of a table");
  CLI11_PARSE(app, argc, argv);
  try {
    return Run(Split(problems), seeds, generations_scale, json);
  } catch (const slamtune::InputError& e) {
    std::fprintf(stderr, "bench_nsga3_dtlz: %s\n", e.what());
    return 2;
  }
}
