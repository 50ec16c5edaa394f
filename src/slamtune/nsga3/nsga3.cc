#include "slamtune/nsga3/nsga3.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/nsga3/nsga3_evaluation.h"
#include "slamtune/nsga3/nsga3_survival.h"

namespace slamtune::nsga3 {
namespace {

// Rejects problems NSGA-III cannot run on.
void CheckProblem(const pagmo::problem& prob) {
  const std::string name = prob.get_name();
  if (prob.get_nobj() < 2) {
    throw InputError(fmt::format("NSGA-III needs >= 2 objectives, problem '{}' has {}", name, prob.get_nobj()));
  }
  if (prob.get_nc() != 0) {
    throw InputError(fmt::format("NSGA-III (Part I) handles box constraints only, problem '{}' has {} constraints",
                                 name, prob.get_nc()));
  }
  if (prob.is_stochastic()) {
    throw InputError(fmt::format(
        "problem '{}' is stochastic; NSGA-III reuses known fitness values and needs a deterministic problem", name));
  }
  const auto& [lower, upper] = prob.get_bounds();
  for (std::size_t i = 0; i < lower.size(); ++i) {
    if (!std::isfinite(lower[i]) || !std::isfinite(upper[i])) {
      throw InputError(fmt::format("problem '{}' bound {} is [{}, {}]; NSGA-III's operators need finite bounds", name,
                                   i, lower[i], upper[i]));
    }
  }
}

// Rejects populations of the wrong size or with values NSGA-III cannot use.
void CheckPopulation(const pagmo::population& pop, std::size_t required_size) {
  const pagmo::problem& prob = pop.get_problem();
  if (pop.size() != required_size) {
    throw InputError(
        fmt::format("the population has {} members but NSGA-III is configured for N = {} (nsga3.population_size; 0 = "
                    "smallest multiple of 4 >= the number of reference points)",
                    pop.size(), required_size));
  }
  const std::size_t nx = prob.get_nx(), nix = prob.get_nix();
  for (std::size_t k = 0; k < pop.size(); ++k) {
    for (double value : pop.get_f()[k]) {
      if (!std::isfinite(value)) {
        throw InputError(fmt::format("population member {} has a non-finite objective value {}", k, value));
      }
    }
    for (std::size_t i = nx - nix; i < nx; ++i) {
      const double gene = pop.get_x()[k][i];
      if (gene != std::round(gene)) {
        throw InputError(fmt::format("population member {} has integer gene {} = {}, not an integer", k, i, gene));
      }
    }
  }
}

// Sanity bound on the objective count read back from a saved state.
constexpr std::size_t kMaxStateObjectives = 10'000;

// ideal = min(ideal, f) per objective over all `points`.
void LowerIdeal(const std::vector<std::vector<double>>& points, std::vector<double>& ideal) {
  for (const auto& p : points) {
    for (std::size_t i = 0; i < ideal.size(); ++i) ideal[i] = std::min(ideal[i], p[i]);
  }
}

}  // namespace

const char* ToString(StopReason reason) {
  switch (reason) {
    case StopReason::kNotRun: return "not run";
    case StopReason::kGenerationLimit: return "generation limit reached";
    case StopReason::kCallbackStop: return "stopped by the generation callback";
  }
  return "?";
}

std::string Nsga3Summary::BriefReport() const {
  return fmt::format(
      "NSGA-III: {} generation(s), {}; {} evaluation(s), {} duplicate(s) skipped, {} "
      "normalisation fall-back(s)",
      generations_run, ToString(stop_reason), evaluations, duplicates_skipped, hyperplane_rejections);
}

Nsga3::Nsga3() : Nsga3(Nsga3Options{}) {}

Nsga3::Nsga3(Nsga3Options options, unsigned seed) : options_(std::move(options)), seed_(seed), rng_(seed) {
  options_.Validate();
}

void Nsga3::set_seed(unsigned seed) {
  seed_ = seed;
  rng_.seed(seed);
  ideal_.clear();
}

// Format: the generator's standard text, then "ideal <M> <z_1> ... <z_M>" with each value in
// shortest round-trip form, so a restored run continues bit for bit.
std::string Nsga3::RngState() const {
  std::ostringstream out;
  out << rng_ << "\nideal " << ideal_.size();
  for (double z : ideal_) out << ' ' << fmt::format("{}", z);
  return out.str();
}

void Nsga3::RestoreRngState(const std::string& state) {
  std::istringstream in(state);
  std::mt19937 restored_rng;
  in >> restored_rng;
  std::string tag;
  std::size_t m = 0;
  in >> tag >> m;
  const bool header_ok = !in.fail() && tag == "ideal" && m <= kMaxStateObjectives;
  std::vector<double> restored_ideal(header_ok ? m : 0);
  for (double& z : restored_ideal) in >> z;
  if (!header_ok || in.fail()) {
    throw InputError("nsga3: the saved run state is malformed (expected a generator state, then 'ideal M z_1 .. z_M')");
  }
  rng_ = restored_rng;
  ideal_ = std::move(restored_ideal);
}

std::string Nsga3::get_extra_info() const {
  const auto& v = options_.variation;
  std::string refs =
      options_.reference_points.empty()
          ? fmt::format("Das-Dennis, divisions {} (inner {})", options_.divisions, options_.inner_divisions)
          : fmt::format("{} user-supplied", options_.reference_points.size());
  return fmt::format(
      "\tGenerations: {}\n\tReference points: {}\n\tPopulation size: {}\n\tCrossover: SBX p_c = {}, eta_c = {}\n"
      "\tMutation: polynomial p_m = {}, eta_m = {}\n\tNormalisation: ASF off-axis weight {}, min intercept {}\n"
      "\tBatch evaluator: {}\n\tSeed: {}\n",
      options_.generations, refs,
      options_.population_size == 0 ? std::string("smallest multiple of 4 >= H")
                                    : std::to_string(options_.population_size),
      v.crossover_probability, v.crossover_eta,
      v.mutation_probability ? std::to_string(*v.mutation_probability) : std::string("1/n"), v.mutation_eta,
      options_.normalization.asf_off_axis_weight, options_.normalization.min_intercept,
      bfe_ ? bfe_->get_name() : std::string("none"), seed_);
}

pagmo::population Nsga3::evolve(pagmo::population pop) const {
  // Preamble: validate everything before any state changes.
  pagmo::problem& prob = pop.get_problem();
  CheckProblem(prob);
  const std::size_t m = prob.get_nobj();
  const ReferencePoints reference_points = options_.MakeReferencePoints(m);
  const std::size_t n = options_.RequiredPopulationSize(m);
  CheckPopulation(pop, n);
  const Bounds bounds = prob.get_bounds();
  const std::size_t nix = prob.get_nix();
  history_.clear();
  summary_ = Nsga3Summary{};
  summary_.stop_reason = StopReason::kGenerationLimit;

  std::vector<std::vector<double>> x = pop.get_x();
  std::vector<std::vector<double>> f = pop.get_f();
  // The ideal point covers every generation of the run (§IV-C: the union of S_tau).
  if (ideal_.size() != m) ideal_.assign(m, std::numeric_limits<double>::infinity());
  LowerIdeal(f, ideal_);
  const unsigned long long fevals_at_start = prob.get_fevals();
  for (unsigned gen = 1; gen <= options_.generations; ++gen) {
    // Algorithm 1, step 2: offspring Q_t by random mating, SBX, mutation and integer repair.
    std::vector<std::vector<double>> qx = MakeOffspring(x, n, bounds, nix, options_.variation, rng_);
    OffspringEvaluation evaluation = EvaluateOffspring(prob, bfe_, x, f, qx);
    LowerIdeal(evaluation.fitness, ideal_);
    // Step 3: R_t = P_t u Q_t; steps 4-17: survival.
    x.insert(x.end(), std::make_move_iterator(qx.begin()), std::make_move_iterator(qx.end()));
    f.insert(f.end(), std::make_move_iterator(evaluation.fitness.begin()),
             std::make_move_iterator(evaluation.fitness.end()));
    const SurvivalResult survival = SelectSurvivors(f, n, reference_points, options_.normalization, rng_, ideal_);
    std::vector<std::vector<double>> next_x, next_f;
    next_x.reserve(n);
    next_f.reserve(n);
    for (std::size_t index : survival.survivors) {
      next_x.push_back(std::move(x[index]));
      next_f.push_back(std::move(f[index]));
    }
    x = std::move(next_x);
    f = std::move(next_f);

    GenerationRecord record;
    record.generation = gen;
    record.evaluations = prob.get_fevals();
    record.new_evaluations = evaluation.evaluated;
    record.duplicates_skipped = evaluation.copied_from_population + evaluation.copied_within_batch;
    record.fronts_used = survival.fronts_used;
    record.niched = survival.niched;
    record.ideal = ideal_;
    if (survival.normalization) {
      record.nadir_source = survival.normalization->nadir_source;
      if (!survival.normalization->hyperplane_rejection.empty()) ++summary_.hyperplane_rejections;
    }
    summary_.generations_run = gen;
    summary_.duplicates_skipped += record.duplicates_skipped;
    summary_.evaluations = prob.get_fevals() - fevals_at_start;
    CallbackAction action = CallbackAction::kContinue;
    if (callback_ || options_.record_history) {
      record.x = x;
      record.f = f;
    }
    if (callback_) action = callback_(record, RngState());
    if (!options_.record_history) {
      record.x.clear();
      record.f.clear();
    }
    history_.push_back(std::move(record));
    if (action == CallbackAction::kStop) {
      summary_.stop_reason = StopReason::kCallbackStop;
      break;
    }
  }
  for (std::size_t k = 0; k < n; ++k) pop.set_xf(k, x[k], f[k]);
  return pop;
}

}  // namespace slamtune::nsga3
