#include "slamtune/optim/optimizer.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <pagmo/batch_evaluators/member_bfe.hpp>
#include <pagmo/bfe.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/utils/generic.hpp>
#include <random>

#include "slamtune/common/error.h"
#include "slamtune/common/progress.h"
#include "slamtune/nsga3/nsga3.h"
#include "slamtune/optim/budget_estimate.h"
#include "slamtune/optim/candidate_selection.h"
#include "slamtune/optim/stored_settings.h"
#include "slamtune/optim/tuning_problem.h"

namespace slamtune::optim {
namespace {

using Clock = std::chrono::steady_clock;

nlohmann::json PopulationJson(const std::vector<std::vector<double>>& x, const std::vector<std::vector<double>>& f,
                              const std::string& rng_state) {
  return {{"x", x}, {"f", f}, {"rng", rng_state}};
}

// The decision vector of `a` in `space` (its value of each dimension, in order).
pagmo::vector_double DecisionOf(const SearchSpace& space, const Assignment& a) {
  pagmo::vector_double x;
  for (const Dimension& d : space.dimensions) x.push_back(d.ValueOf(a.at(d.name)));
  return x;
}

// The initial population: N random decision vectors (integer genes integral) from `seed`, the
// first ones replaced by `seeds`, evaluated as one batch.
pagmo::population InitialPopulation(const pagmo::problem& problem, const SearchSpace& space,
                                    const std::vector<Assignment>& seeds, std::size_t n, unsigned seed) {
  pagmo::population pop(problem, 0u, seed);
  pagmo::detail::random_engine_type rng(seed);
  std::vector<pagmo::vector_double> xs;
  pagmo::vector_double flat;
  for (std::size_t i = 0; i < n; ++i) {
    xs.push_back(pagmo::random_decision_vector(problem, rng));
    if (i < seeds.size()) xs.back() = DecisionOf(space, seeds[i]);
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
    if (r.status == RunStatus::kOk) return;
  }
  std::string example;
  if (!records.empty()) {
    for (const auto& [name, value] : records.front().params) {
      example += fmt::format("{}{}={}", example.empty() ? "" : " ", name, value);
    }
    example = fmt::format(" (e.g. {}: {})", example, records.front().reason);
  }
  throw InputError(
      fmt::format("every SLAM run of {} failed{}: nothing to compare; check the search space", what, example));
}

}  // namespace

void OptimizeSettings::Validate() const {
  space.Validate("search space");
  settling.Validate();
  if (population < 4) throw InputError(fmt::format("--population = {} is out of range: must be >= 4", population));
  if (generations < 1) throw InputError(fmt::format("--generations = {} is out of range: must be >= 1", generations));
  if (divisions < 1) throw InputError(fmt::format("--divisions = {} is out of range: must be >= 1", divisions));
  for (const Assignment& individual : seeds) {
    for (const Dimension& d : space.dimensions) {
      if (!individual.count(d.name)) throw InputError("an initial individual has no value for " + d.name);
    }
  }
}

nlohmann::json OptimizeSettings::ToJson() const {
  nlohmann::json j = {{"log", source.log_label},
                      {"relations", source.relations_label},
                      {"space", space.Fingerprint()},
                      {"default", default_assignment},
                      {"divisions", divisions},
                      {"population", population},
                      {"generations", generations},
                      {"seed", seed},
                      {"engine", engine},
                      {"objectives", objectives.name()},
                      {"settling", settling.ToJson()}};
  if (!seeds.empty()) j["seeds"] = seeds;  // absent without: older folders compare equal
  return j;
}

namespace {

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

// Preamble, before any work: with kResume the stored run's settings must equal `settings`;
// a new run needs a run database without one and stores them. Returns settings.ToJson().
nlohmann::json OpenRun(const OptimizeSettings& settings, EvaluationStore& store, OptimizationStart start) {
  settings.Validate();
  const nlohmann::json settings_json = settings.ToJson();
  const auto stored_raw = store.Settings();
  const std::optional<nlohmann::json> stored =
      stored_raw ? std::optional<nlohmann::json>(UpgradeStoredSettings(*stored_raw, settings_json)) : std::nullopt;
  if (start == OptimizationStart::kResume) {
    if (!stored) throw InputError(store.path(), 0, "--resume: this folder holds no slamtune optimisation");
    if (*stored != settings_json) {
      std::string diff;
      for (const auto& [key, value] : settings_json.items()) {
        if (!stored->contains(key) || (*stored)[key] != value) diff += (diff.empty() ? "" : ", ") + key;
      }
      throw InputError(store.path(), 0,
                       "--resume: the run was made with different settings (" + diff +
                           "); --resume DIR alone continues it as it was started (options that do not change "
                           "results, such as --jobs and --quiet, may be added); other settings need a new --out");
    }
  } else {
    if (stored) {
      throw InputError(store.path(), 0, "the folder already holds an optimisation; use --resume or a new --out");
    }
    store.StartRun(settings_json, settings.invocation);
  }
  return settings_json;
}

// Generation `generation` as saved: {"x": decisions, "f": objectives, "rng": state}.
GenerationSnapshot SnapshotOf(unsigned generation, const nlohmann::json& saved) {
  return {static_cast<int>(generation), saved.at("x").get<std::vector<std::vector<double>>>(),
          saved.at("f").get<std::vector<std::vector<double>>>()};
}

GenerationSnapshot StoredSnapshot(const EvaluationStore& store, unsigned generation) {
  return SnapshotOf(generation, *store.Generation(static_cast<int>(generation)));
}

// Generations 1, half of `last` and `last`, without repeats.
std::vector<unsigned> FigureGenerations(unsigned last) {
  std::vector<unsigned> gens{1, std::max(1u, last / 2), last};
  gens.erase(std::unique(gens.begin(), gens.end()), gens.end());
  return gens;
}

// The generations of one optimisation: generation 0 (or, resuming, the last saved one), then
// NSGA-III until the budget is spent or the answer has settled; each finished generation is
// saved, shown and fed to the settling rule, and the figures' generations are kept.
class Generations {
 public:
  Generations(const OptimizeSettings& settings, BatchEvaluator& evaluator, EvaluationStore& store,
              const OptimizeHooks& hooks, Clock::time_point start);

  // Generation 0, or with kResume the last saved generation and the generator's state; the
  // settling rule sees every saved generation again.
  void Begin(OptimizationStart start);
  // NSGA-III over the generations left, unless the run has settled.
  void Evolve();

  const pagmo::population& population() const { return pop_; }
  unsigned done() const { return done_gens_; }
  const SettlingRule& settling() const { return settling_; }
  // Generations 1, G/2 and G of the budget G, or 1, s/2 and s of a run settled at s, in order.
  std::vector<GenerationSnapshot> Snapshots() const;

 private:
  // Whether a progress line is shown whenever it comes (generation ends, announcements) or
  // only when the progress display is due for one (OptimizeHooks::progress's `force`).
  enum class Show { kWhenDue, kAlways };
  // The progress line during generation `gen` or at its end.
  void Report(unsigned gen, Show show);
  void Announce(const std::string& line) const {
    if (hooks_.progress) hooks_.progress(line, /*force=*/true);
  }
  void StartFromGenerationZero();
  void RestoreGeneration(int saved);
  nsga3::CallbackAction Finished(const nsga3::GenerationRecord& record, const std::string& state);

  const OptimizeSettings& settings_;
  BatchEvaluator& evaluator_;
  EvaluationStore& store_;
  const OptimizeHooks& hooks_;
  const Clock::time_point start_;
  const unsigned total_gens_;
  const std::vector<unsigned> snapshot_gens_;
  pagmo::problem problem_;
  pagmo::population pop_;
  std::string rng_state_;
  unsigned done_gens_ = 0;
  // Progress counts what the summary counts: SLAM runs stored (those of an interrupted earlier
  // process included) and requests served without a run. The time left extrapolates this
  // process's finished generations.
  const std::size_t runs_before_;
  // The generation this process started from (0 unless resumed).
  unsigned first_gen_here_ = 0;
  // When this process's latest generation ended, and how long it took: the time left goes at that
  // pace (generation 0's random sets, most of them stopped early in a front-end search, are no
  // guide to the later ones).
  Clock::time_point last_generation_end_;
  double last_generation_s_ = -1.0;
  std::vector<std::vector<double>> current_f_;  // objectives of the latest population
  SettlingRule settling_;
  std::vector<GenerationSnapshot> snapshots_;
};

Generations::Generations(const OptimizeSettings& settings, BatchEvaluator& evaluator, EvaluationStore& store,
                         const OptimizeHooks& hooks, Clock::time_point start)
    : settings_(settings),
      evaluator_(evaluator),
      store_(store),
      hooks_(hooks),
      start_(start),
      total_gens_(settings.generations),
      snapshot_gens_(FigureGenerations(settings.generations)),
      problem_(TuningProblem(settings.space, settings.objectives,
                             std::shared_ptr<BatchEvaluator>(&evaluator, [](BatchEvaluator*) {}))),
      pop_(problem_, 0u, settings.seed),
      runs_before_(store.Count()),
      settling_(settings.settling, settings.space, [objectives = settings.objectives](const std::vector<double>& f) {
        return objectives.IsFailureScore(f);
      }) {}

void Generations::Report(unsigned gen, Show show) {
  if (!hooks_.progress) return;
  const auto st = evaluator_.stats();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double rate = elapsed > 0 ? st.evaluated / elapsed * 60.0 : 0.0;
  // At the latest generation's pace (the mean of this process's generations until one has
  // ended), the budget's generations still to come; the early stop usually ends sooner.
  const unsigned gens_here = done_gens_ - first_gen_here_ + (first_gen_here_ == 0 ? 1 : 0);
  const double pace = last_generation_s_ >= 0 ? last_generation_s_ : gens_here > 0 ? elapsed / gens_here : -1;
  const double left = pace >= 0 ? pace * (total_gens_ - done_gens_) : -1;
  hooks_.progress(
      fmt::format("gen {}/{} | SLAM runs {} | cache hits {} | {:.1f} runs/min | {} | left {}{}", gen, total_gens_,
                  runs_before_ + st.evaluated, st.cache_hits, rate, BestObjectives(settings_.objectives, current_f_),
                  settings_.settling.enabled ? "<= " : "", FormatDuration(left)),
      show == Show::kAlways);
}

void Generations::StartFromGenerationZero() {
  Announce(fmt::format("generation 0: {} random parameter sets", settings_.population));
  pop_ = InitialPopulation(problem_, settings_.space, settings_.seeds, settings_.population, settings_.seed);
  store_.PutGeneration(
      0, PopulationJson({pop_.get_x().begin(), pop_.get_x().end()}, {pop_.get_f().begin(), pop_.get_f().end()}, ""));
  last_generation_end_ = Clock::now();
  if (hooks_.progress && total_gens_ > 0) {
    const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    Announce(BudgetEstimateLine(settings_.population, total_gens_, evaluator_.stats().evaluated, seconds,
                                settings_.settling.enabled));
  }
}

void Generations::RestoreGeneration(int saved_generation) {
  const nlohmann::json saved = *store_.Generation(saved_generation);
  const auto xs = saved.at("x").get<std::vector<std::vector<double>>>();
  const auto fs = saved.at("f").get<std::vector<std::vector<double>>>();
  for (std::size_t i = 0; i < xs.size(); ++i) pop_.push_back(xs[i], fs[i]);
  rng_state_ = saved.at("rng").get<std::string>();
  done_gens_ = static_cast<unsigned>(saved_generation);
  first_gen_here_ = done_gens_;
  last_generation_end_ = Clock::now();
  Announce(fmt::format("resuming after generation {}/{}", done_gens_, total_gens_));
}

void Generations::Begin(OptimizationStart start) {
  const int last_saved = start == OptimizationStart::kResume ? store_.LastGeneration() : -1;
  if (last_saved >= 0) {
    RestoreGeneration(last_saved);
  } else {
    StartFromGenerationZero();
  }
  current_f_.assign(pop_.get_f().begin(), pop_.get_f().end());
  // The settling rule sees every finished generation from generation 0, the saved ones replayed
  // on a resume.
  for (unsigned g = 0; g <= done_gens_; ++g) {
    if (!store_.Generation(static_cast<int>(g))) continue;  // a folder that kept no generation 0
    const GenerationSnapshot saved = StoredSnapshot(store_, g);
    settling_.Update(g, saved.decisions, saved.objectives);
  }
  RequireAnySuccess(RecordsOf(evaluator_, settings_.space, {pop_.get_x().begin(), pop_.get_x().end()}),
                    done_gens_ == 0 ? "the initial population" : "the saved population");
  for (unsigned g : snapshot_gens_) {  // figures of generations finished before a resume
    if (g > done_gens_) continue;
    if (auto saved = store_.Generation(static_cast<int>(g))) snapshots_.push_back(SnapshotOf(g, *saved));
  }
}

nsga3::CallbackAction Generations::Finished(const nsga3::GenerationRecord& record, const std::string& state) {
  // Saved first: a kill after this line loses nothing of this generation.
  store_.PutGeneration(static_cast<int>(done_gens_ + 1), PopulationJson(record.x, record.f, state));
  ++done_gens_;
  const Clock::time_point now = Clock::now();
  last_generation_s_ = std::chrono::duration<double>(now - last_generation_end_).count();
  last_generation_end_ = now;
  current_f_ = record.f;
  if (std::find(snapshot_gens_.begin(), snapshot_gens_.end(), done_gens_) != snapshot_gens_.end()) {
    snapshots_.push_back({static_cast<int>(done_gens_), record.x, record.f});
  }
  Report(done_gens_, Show::kAlways);
  if (!settling_.Update(done_gens_, record.x, record.f)) return nsga3::CallbackAction::kContinue;
  Announce(settling_.Describe(total_gens_));
  return nsga3::CallbackAction::kStop;
}

void Generations::Evolve() {
  if (done_gens_ >= total_gens_ || settling_.settled()) return;
  nsga3::Nsga3Options options;
  options.generations = total_gens_ - done_gens_;
  options.divisions = settings_.divisions;
  options.population_size = settings_.population;
  nsga3::Nsga3 algorithm(options, settings_.seed);
  if (!rng_state_.empty()) algorithm.RestoreRngState(rng_state_);
  algorithm.set_bfe(pagmo::bfe(pagmo::member_bfe{}));
  evaluator_.SetProgressCallback(
      [this](const EvaluationRecord&, const BatchEvaluatorStats&) { Report(done_gens_ + 1, Show::kWhenDue); });
  algorithm.set_generation_callback(
      [this](const nsga3::GenerationRecord& record, const std::string& state) { return Finished(record, state); });
  pop_ = algorithm.evolve(pop_);
  evaluator_.SetProgressCallback(nullptr);
}

std::vector<GenerationSnapshot> Generations::Snapshots() const {
  std::vector<GenerationSnapshot> snapshots;
  if (settling_.settled()) {
    // A settled run's figures are generations 1, s/2 and s, whether it settled now or before a resume.
    for (unsigned g : FigureGenerations(settling_.settled_at())) snapshots.push_back(StoredSnapshot(store_, g));
  } else {
    snapshots = snapshots_;
  }
  std::sort(snapshots.begin(), snapshots.end(),
            [](const auto& a, const auto& b) { return a.generation < b.generation; });
  return snapshots;
}

// The candidates an engineer needs from the final population, the verdict on the
// recommendation against the base configuration, and the evaluated sets equivalent to it.
void ChooseAnswer(const OptimizeSettings& settings, const std::vector<EvaluationRecord>& final_records,
                  BatchEvaluator& evaluator, EvaluationStore& store, OptimizeResult& result) {
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
      {"knee",
       "the final front's member closest to the ideal point (objectives normalised by the front's range)",
       final_records[knee],
       {},
       {},
       {}},
      {"worst",
       "the evaluated set with the largest sum of normalised objectives (for contrast)",
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
  result.node_mode = settings.node_mode;
}

// The candidate with the lowest translational error, when there is ground truth.
void NameLowestError(OptimizeResult& result) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : result.candidates) {
    if (c.record.has_gt && c.record.trans_mean_m < best) {
      best = c.record.trans_mean_m;
      result.lowest_error_label = c.label;
    }
  }
}

void RenderCandidateMaps(const std::function<CandidateMap(const Assignment&)>& render_map, OptimizeResult& result) {
  for (auto& c : result.candidates) {
    CandidateMap rendered = render_map(c.record.params);
    c.map = std::move(rendered.map);
    c.loop_edges = std::move(rendered.loop_edges);
    c.path = std::move(rendered.path);
  }
}

// Every stored generation up to `last`, the initial population (0) included, for the history figure.
OptimizationHistory StoredHistory(const EvaluationStore& store, unsigned last, const ObjectiveSet& objectives) {
  std::vector<std::vector<std::vector<double>>> populations;
  for (unsigned g = 0; g <= last; ++g) {
    const std::optional<nlohmann::json> saved = store.Generation(static_cast<int>(g));
    if (!saved) break;
    populations.push_back(saved->at("f").get<std::vector<std::vector<double>>>());
  }
  return SummarizeGenerations(populations, objectives);
}

}  // namespace

OptimizeResult RunOptimization(const OptimizeSettings& settings, BatchEvaluator& evaluator, EvaluationStore& store,
                               OptimizationStart start, const OptimizeHooks& hooks) {
  const nlohmann::json settings_json = OpenRun(settings, store, start);
  if (hooks.started) hooks.started();

  const auto started_at = Clock::now();
  Generations generations(settings, evaluator, store, hooks, started_at);
  OptimizeResult result;
  result.source = settings.source;
  result.space = settings.space;
  result.objectives = settings.objectives;
  result.population = settings.population;
  result.settings = settings_json;
  generations.Begin(start);
  generations.Evolve();
  result.snapshots = generations.Snapshots();

  // Choosing the answer.
  const std::vector<pagmo::vector_double> final_x(generations.population().get_x().begin(),
                                                  generations.population().get_x().end());
  const std::vector<EvaluationRecord> final_records = RecordsOf(evaluator, settings.space, final_x);
  RequireAnySuccess(final_records, "the final population");
  ChooseAnswer(settings, final_records, evaluator, store, result);
  if (!settings.source.relations_label.empty()) NameLowestError(result);
  if (hooks.render_map) RenderCandidateMaps(hooks.render_map, result);
  result.history = StoredHistory(store, generations.done(), settings.objectives);
  const auto st = evaluator.stats();
  result.evaluation_count = store.Count();
  result.generations_run = generations.done();
  result.settling = generations.settling().Describe(settings.generations);
  result.cache_hits = st.cache_hits;
  result.wall_s = std::chrono::duration<double>(Clock::now() - started_at).count();
  return result;
}

}  // namespace slamtune::optim
