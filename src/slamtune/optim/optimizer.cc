#include "slamtune/optim/optimizer.h"

#include <fmt/format.h>
#include <pagmo/batch_evaluators/member_bfe.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/utils/generic.hpp>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <random>

#include "slamtune/common/error.h"
#include "slamtune/common/progress.h"
#include "slamtune/nsga3/nsga3.h"
#include "slamtune/optim/budget_estimate.h"
#include "slamtune/optim/candidate_selection.h"
#include "slamtune/optim/tuning_problem.h"

namespace slamtune::optim {
namespace {

using Clock = std::chrono::steady_clock;

nlohmann::json PopulationJson(const std::vector<std::vector<double>>& x, const std::vector<std::vector<double>>& f,
                              const std::string& rng_state) {
  return {{"x", x}, {"f", f}, {"rng", rng_state}};
}

// The initial population: N random decision vectors (integer genes integral) from `seed`,
// evaluated as one batch.
pagmo::population InitialPopulation(const pagmo::problem& problem, std::size_t n, unsigned seed) {
  pagmo::population pop(problem, 0u, seed);
  pagmo::detail::random_engine_type rng(seed);
  std::vector<pagmo::vector_double> xs;
  pagmo::vector_double flat;
  for (std::size_t i = 0; i < n; ++i) {
    xs.push_back(pagmo::random_decision_vector(problem, rng));
    flat.insert(flat.end(), xs.back().begin(), xs.back().end());
  }
  const pagmo::vector_double fs = problem.batch_fitness(flat);
  const std::size_t m = problem.get_nobj();
  for (std::size_t i = 0; i < n; ++i) {
    pop.push_back(xs[i], pagmo::vector_double(fs.begin() + static_cast<long>(i * m),
                                              fs.begin() + static_cast<long>((i + 1) * m)));
  }
  return pop;
}

std::vector<EvaluationRecord> RecordsOf(BatchEvaluator& evaluator, const SearchSpace& space,
                                        const std::vector<pagmo::vector_double>& xs) {
  std::vector<Assignment> batch;
  for (const auto& x : xs) batch.push_back(space.Assign(x));
  return evaluator.Evaluate(batch);
}

// Stops with a readable error when no run of `records` succeeded: nothing can be ranked, and
// every later generation would fail the same way.
void RequireAnySuccess(const std::vector<EvaluationRecord>& records, const std::string& what) {
  for (const EvaluationRecord& r : records) {
    if (r.status == "ok") return;
  }
  std::string example;
  if (!records.empty()) {
    for (const auto& [name, value] : records.front().params) {
      example += fmt::format("{}{}={}", example.empty() ? "" : " ", name, value);
    }
    example = fmt::format(" (e.g. {}: {})", example, records.front().reason);
  }
  throw InputError(fmt::format("every SLAM run of {} failed{}: nothing to compare; check the search space", what,
                               example));
}

}  // namespace

void OptimizeSettings::Validate() const {
  space.Validate("search space");
  settling.Validate();
  if (population < 4) throw InputError(fmt::format("--population = {} is out of range: must be >= 4", population));
  if (generations < 1) throw InputError(fmt::format("--generations = {} is out of range: must be >= 1", generations));
  if (divisions < 1) throw InputError(fmt::format("--divisions = {} is out of range: must be >= 1", divisions));
}

nlohmann::json OptimizeSettings::ToJson() const {
  return {{"log", log_path},           {"relations", relations_path}, {"space", space.Fingerprint()},
          {"default", default_assignment}, {"divisions", divisions},  {"population", population},
          {"generations", generations},  {"seed", seed},              {"engine", engine},
          {"objectives", objectives.name()},
          {"settling", {{"enabled", settling.enabled}, {"tolerance", settling.tolerance}, {"window", settling.window}}}};
}

namespace {

// Stored settings as today's ToJson writes them: folders written before objective sets
// existed were optimised on the paper's objectives.
nlohmann::json UpgradedSettings(nlohmann::json stored) {
  if (stored.is_object() && !stored.contains("objectives")) {
    stored["objectives"] = ObjectiveSet::NameOf(ObjectiveSetKind::kPaper);
  }
  // ... and ran their whole budget.
  if (stored.is_object() && !stored.contains("settling")) {
    const SettlingOptions fixed{false};
    stored["settling"] = {{"enabled", fixed.enabled}, {"tolerance", fixed.tolerance}, {"window", fixed.window}};
  }
  return stored;
}

// "best u_h 0.0123 n_c 4512 n_e 3" over the latest population.
std::string BestObjectives(const ObjectiveSet& objectives, const std::vector<std::vector<double>>& population) {
  std::string out = "best";
  for (std::size_t k = 0; k < objectives.size(); ++k) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : population) best = std::min(best, f[k]);
    out += fmt::format(" {} {:.4g}", InfoOf(objectives.objectives()[k]).short_name, best);
  }
  return out;
}

}  // namespace

OptimizeResult RunOptimization(const OptimizeSettings& settings, BatchEvaluator& evaluator, EvaluationStore& store,
                               bool resume, const OptimizeHooks& hooks) {
  // Preamble: validate everything before any work.
  settings.Validate();
  const nlohmann::json settings_json = settings.ToJson();
  const auto stored_raw = store.Settings();
  const std::optional<nlohmann::json> stored =
      stored_raw ? std::optional<nlohmann::json>(UpgradedSettings(*stored_raw)) : std::nullopt;
  if (resume) {
    if (!stored) throw InputError(store.path(), 0, "--resume: this folder holds no slamtune optimisation");
    if (*stored != settings_json) {
      std::string diff;
      for (const auto& [key, value] : settings_json.items()) {
        if (!stored->contains(key) || (*stored)[key] != value) diff += (diff.empty() ? "" : ", ") + key;
      }
      throw InputError(store.path(), 0, "--resume: the run was made with different settings (" + diff + ")");
    }
  } else {
    if (stored) {
      throw InputError(store.path(), 0, "the folder already holds an optimisation; use --resume or a new --out");
    }
    store.StartRun(settings_json, settings.invocation);
  }
  if (hooks.started) hooks.started();

  const auto start = Clock::now();
  auto shared = std::shared_ptr<BatchEvaluator>(&evaluator, [](BatchEvaluator*) {});
  pagmo::problem problem{TuningProblem(settings.space, settings.objectives, shared)};

  OptimizeResult result;
  result.log_path = settings.log_path;
  result.log_input = settings.log_input;
  result.relations_path = settings.relations_path;
  result.space = settings.space;
  result.objectives = settings.objectives;
  result.settings = settings_json;

  const unsigned total_gens = settings.generations;
  std::vector<unsigned> snapshot_gens{1, std::max(1u, total_gens / 2), total_gens};
  snapshot_gens.erase(std::unique(snapshot_gens.begin(), snapshot_gens.end()), snapshot_gens.end());

  unsigned done_gens = 0;
  std::vector<std::vector<double>> current_f;  // objectives of the latest population
  // Progress counts what the summary counts: SLAM runs stored (those of an interrupted earlier
  // process included) and requests served without a run. The time left extrapolates this
  // process's finished generations.
  const std::size_t runs_before = store.Count();
  unsigned first_gen_here = 0;  // the generation this process started from (0 unless resumed)
  auto report = [&](unsigned gen, bool force) {
    if (!hooks.progress) return;
    const auto st = evaluator.stats();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const double rate = elapsed > 0 ? st.evaluated / elapsed * 60.0 : 0.0;
    // A fresh run also spent its time on generation 0.
    const unsigned gens_here = done_gens - first_gen_here + (first_gen_here == 0 ? 1 : 0);
    const double left = gens_here > 0 ? elapsed / gens_here * (total_gens - done_gens) : -1;
    hooks.progress(fmt::format("gen {}/{} | SLAM runs {} | cache hits {} | {:.1f} runs/min | {} | left {}", gen,
                               total_gens, runs_before + st.evaluated, st.cache_hits, rate,
                               BestObjectives(settings.objectives, current_f), FormatDuration(left)),
                   force);
  };

  // Generation 0 is the initial population; when resuming, start from the last saved one.
  pagmo::population pop(problem, 0u, settings.seed);
  std::string rng_state;
  const int last_saved = resume ? store.LastGeneration() : -1;
  if (last_saved >= 0) {
    const nlohmann::json saved = *store.Generation(last_saved);
    const auto xs = saved.at("x").get<std::vector<std::vector<double>>>();
    const auto fs = saved.at("f").get<std::vector<std::vector<double>>>();
    for (std::size_t i = 0; i < xs.size(); ++i) pop.push_back(xs[i], fs[i]);
    rng_state = saved.at("rng").get<std::string>();
    done_gens = static_cast<unsigned>(last_saved);
    first_gen_here = done_gens;
    if (hooks.progress) hooks.progress(fmt::format("resuming after generation {}/{}", done_gens, total_gens), true);
  } else {
    if (hooks.progress) hooks.progress(fmt::format("generation 0: {} random parameter sets", settings.population), true);
    pop = InitialPopulation(problem, settings.population, settings.seed);
    store.PutGeneration(0, PopulationJson({pop.get_x().begin(), pop.get_x().end()},
                                          {pop.get_f().begin(), pop.get_f().end()}, ""));
    if (hooks.progress && total_gens > 0) {
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      hooks.progress(BudgetEstimateLine(settings.population, total_gens, evaluator.stats().evaluated, seconds,
                                        settings.settling.enabled),
                     true);
    }
  }
  current_f.assign(pop.get_f().begin(), pop.get_f().end());
  // The settling rule sees every finished generation, the saved ones replayed on a resume.
  SettlingRule settling(settings.settling, settings.space);
  for (unsigned g = 1; g <= done_gens; ++g) {
    const nlohmann::json saved = *store.Generation(static_cast<int>(g));
    settling.Update(g, saved.at("x").get<std::vector<std::vector<double>>>(),
                    saved.at("f").get<std::vector<std::vector<double>>>());
  }
  RequireAnySuccess(RecordsOf(evaluator, settings.space, {pop.get_x().begin(), pop.get_x().end()}),
                    done_gens == 0 ? "the initial population" : "the saved population");
  for (unsigned g : snapshot_gens) {  // figures of generations finished before a resume
    if (g > done_gens) continue;
    if (auto saved = store.Generation(static_cast<int>(g))) {
      result.snapshots.push_back({static_cast<int>(g), saved->at("x").get<std::vector<std::vector<double>>>(),
                                  saved->at("f").get<std::vector<std::vector<double>>>()});
    }
  }

  if (done_gens < total_gens && !settling.settled()) {
    nsga3::Nsga3Options options;
    options.generations = total_gens - done_gens;
    options.divisions = settings.divisions;
    options.population_size = settings.population;
    nsga3::Nsga3 algorithm(options, settings.seed);
    if (!rng_state.empty()) algorithm.RestoreRngState(rng_state);
    algorithm.set_bfe(pagmo::bfe(pagmo::member_bfe{}));
    evaluator.SetProgressCallback(
        [&](const EvaluationRecord&, const BatchEvaluatorStats&) { report(done_gens + 1, false); });
    algorithm.set_generation_callback([&](const nsga3::GenerationRecord& record, const std::string& state) {
      // Saved first: a kill after this line loses nothing of this generation.
      store.PutGeneration(static_cast<int>(done_gens + 1), PopulationJson(record.x, record.f, state));
      ++done_gens;
      current_f = record.f;
      if (std::find(snapshot_gens.begin(), snapshot_gens.end(), done_gens) != snapshot_gens.end()) {
        result.snapshots.push_back({static_cast<int>(done_gens), record.x, record.f});
      }
      report(done_gens, true);
      if (!settling.Update(done_gens, record.x, record.f)) return nsga3::CallbackAction::kContinue;
      if (hooks.progress) hooks.progress(settling.Describe(total_gens), true);
      return nsga3::CallbackAction::kStop;
    });
    pop = algorithm.evolve(pop);
    evaluator.SetProgressCallback(nullptr);
  }

  // A settled run's figures are generations 1, s/2 and s, whether it settled now or before a resume.
  if (settling.settled()) {
    const unsigned s = settling.settled_at();
    std::vector<unsigned> gens{1, std::max(1u, s / 2), s};
    gens.erase(std::unique(gens.begin(), gens.end()), gens.end());
    result.snapshots.clear();
    for (unsigned g : gens) {
      const nlohmann::json saved = *store.Generation(static_cast<int>(g));
      result.snapshots.push_back({static_cast<int>(g), saved.at("x").get<std::vector<std::vector<double>>>(),
                                  saved.at("f").get<std::vector<std::vector<double>>>()});
    }
  }

  // Choosing the answer.
  const std::vector<pagmo::vector_double> final_x(pop.get_x().begin(), pop.get_x().end());
  const std::vector<EvaluationRecord> final_records = RecordsOf(evaluator, settings.space, final_x);
  RequireAnySuccess(final_records, "the final population");
  result.evaluations = store.All();
  const Recommendation rec = RecommendByMajority(final_records, settings.objectives);
  result.recommended_share = rec.share;
  const EvaluationRecord defaults = evaluator.Evaluate({settings.default_assignment}).front();
  const std::size_t knee = Knee(final_records, settings.objectives);
  result.evaluations = store.All();
  const std::size_t worst = Worst(result.evaluations, settings.objectives);

  result.candidates = {
      {"recommended",
       fmt::format("the parameter set shared by most individuals of the final population ({} of {})", rec.share,
                   final_records.size()),
       final_records[rec.index],
       {},
       {},
       {}},
      {"knee", "the final front's member closest to the ideal point (objectives normalised by the front's range)",
       final_records[knee],
       {},
       {},
       {}},
      {"worst", "the evaluated set with the largest sum of normalised objectives (for contrast)",
       result.evaluations[worst],
       {},
       {},
       {}},
      {"default", settings.base_label + ": the base configuration's values", defaults, {}, {}, {}},
  };
  result.equivalent_region =
      FindEquivalentRegion(result.evaluations, final_records[rec.index], settings.space, settings.objectives);
  VerdictOptions verdict_options;
  verdict_options.base_label = settings.base_label;
  verdict_options.objectives = settings.objectives;
  const VerdictSummary verdict = Verdict(final_records[rec.index], defaults, verdict_options);
  result.verdict = verdict.text;
  result.verdict_kind = verdict.kind;
  result.base_label = settings.base_label;
  if (!settings.relations_path.empty()) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& c : result.candidates) {
      if (c.record.has_gt && c.record.trans_mean_m < best) {
        best = c.record.trans_mean_m;
        result.lowest_error_label = c.label;
      }
    }
  }
  if (hooks.render_map) {
    for (auto& c : result.candidates) {
      CandidateMap rendered = hooks.render_map(c.record.params);
      c.map = std::move(rendered.map);
      c.loop_edges = std::move(rendered.loop_edges);
      c.path = std::move(rendered.path);
    }
  }
  // Every stored generation, the initial population (0) included, for the history figure.
  std::vector<std::vector<std::vector<double>>> populations;
  for (unsigned g = 0; g <= done_gens; ++g) {
    const std::optional<nlohmann::json> saved = store.Generation(static_cast<int>(g));
    if (!saved) break;
    populations.push_back(saved->at("f").get<std::vector<std::vector<double>>>());
  }
  result.history = SummarizeGenerations(populations, settings.objectives);
  std::sort(result.snapshots.begin(), result.snapshots.end(),
            [](const auto& a, const auto& b) { return a.generation < b.generation; });
  const auto st = evaluator.stats();
  result.evaluation_count = store.Count();
  result.generations_run = done_gens;
  result.settling = settling.Describe(total_gens);
  result.cache_hits = st.cache_hits;
  result.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace slamtune::optim
